// Running a command as a child process with a time limit, its output going to a log file: the
// harness's run_program (processes/child.h) with what `crosscheck mutate` adds to it: SIGINT and
// SIGTERM kill the running children, a program that cannot start is a line in its log, and the
// wall-clock time.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace cc::tool {

/// How a child process ended.
struct ChildResult {
  int exit_status = -1;    // the exit status; -1 when it was killed by a signal or could not start
  bool timed_out = false;  // killed (with its whole process group) because it ran past the limit
  bool stopped = false;    // killed (with its whole process group) because `stop` asked for it,
                           // or SIGINT or SIGTERM arrived (interrupted())
  bool started = true;     // false when the program could not be started (its name is in the log)
  double seconds = 0;      // wall-clock time
};

/// Runs `argv` (argv[0] looked up in PATH) in its own process group, in directory `cwd` (empty:
/// the current one), with stdout appended to `log` and stderr to `err_log` (empty: `log` too).
/// After `timeout_seconds` (<= 0: none) the whole group is killed and timed_out is set. `stop`,
/// if given, is asked every 50 ms while the child runs; when it returns true, or once
/// interrupted(), the whole group is killed and stopped is set. Safe to call from several
/// threads.
ChildResult run_child(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                      const std::filesystem::path& log, double timeout_seconds,
                      const std::filesystem::path& err_log = {}, const std::function<bool()>& stop = {});

/// Makes SIGINT and SIGTERM kill the running children (their own process groups do not get the
/// terminal's signal) and set interrupted(), instead of ending this process.
void interrupt_children_on_signal();

/// True once SIGINT or SIGTERM arrived after interrupt_children_on_signal().
bool interrupted();

/// Seconds on a monotonic clock, for measuring durations.
double monotonic_seconds();

}  // namespace cc::tool
