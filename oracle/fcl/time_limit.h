// A time limit for oracle calls that may never return (internal to oracle/fcl).
#pragma once

#include <functional>

namespace cc::fcl_oracle {

/// Runs f. If it has not returned after `seconds` of CPU time, abandons it with a jump out of a
/// SIGVTALRM handler and returns false. (CPU time, not SIGALRM: libFuzzer's own timeout uses
/// SIGALRM and the real-time timer.) Never while f is inside the C or C++ runtime (malloc, the
/// loader, the unwinder: a jump out would leave the heap or a lock broken): the jump then waits,
/// a millisecond of CPU time at a time, until f is back in its own code. Only for
/// single-threaded code that holds no locks of its own and whose abandoned heap objects may
/// leak: libccd's GJK and MPR loops, which do not terminate on some inputs (long, thin
/// triangles; huge coordinates).
bool run_with_time_limit(double seconds, const std::function<void()>& f);

/// How a guarded call ended.
enum class Guarded { returned, timed_out, aborted };
/// As run_with_time_limit, and also abandons f when it calls abort() (a failed assert() inside
/// FCL's libccd code, e.g. doSimplex2's "A is not in region 1"), with the same caveats.
Guarded run_guarded(double seconds, const std::function<void()>& f);

/// How many guarded calls this process has abandoned (timed out or aborted) so far.
int abandoned_calls();

/// The limit used for libccd calls: they take microseconds when they return at all.
inline constexpr double kLibccdTimeLimit = 0.02;

}  // namespace cc::fcl_oracle
