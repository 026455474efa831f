// SIGINT, SIGTERM, SIGHUP (the terminal gone) and SIGPIPE (the reader of the output gone) as
// requests to a long run: the first asks it to stop and keep what it has (the summary, the JSON,
// every finding), a second to stop at once (store what it has raw).
#pragma once

namespace cc::harness {

/// Counts SIGINT, SIGTERM, SIGHUP and SIGPIPE from now on instead of ending the process (idempotent; forked
/// children inherit the handlers and count their own). Handlers restart interrupted calls.
void count_interrupts();

/// How many of them arrived since count_interrupts() (or forget_interrupts()).
int interrupts();

/// The last of them, or 0.
int last_interrupt();

/// Starts counting again from 0 (a worker forgets its parent's count).
void forget_interrupts();

}  // namespace cc::harness
