// SIGINT and SIGTERM as requests to a long run: the first asks it to stop and keep what it has
// (the summary, the JSON, every finding), a second to stop at once (store what it has raw).
#pragma once

namespace cc::harness {

/// Counts SIGINT and SIGTERM from now on instead of ending the process (idempotent; forked
/// children inherit the handlers and count their own). Handlers restart interrupted calls.
void count_interrupts();

/// How many SIGINT or SIGTERM arrived since count_interrupts() (or forget_interrupts()).
int interrupts();

/// The last of them (SIGINT or SIGTERM), or 0.
int last_interrupt();

/// Starts counting again from 0 (a worker forgets its parent's count).
void forget_interrupts();

}  // namespace cc::harness
