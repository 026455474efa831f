// Running a function in a child process: the one place where the project forks. A crash, a hang
// or a damaged heap in the child (a peer library's, a user's code) costs the child, never the
// caller.
#pragma once

#include <sys/types.h>

#include <functional>
#include <string>
#include <string_view>

namespace cc::harness {

/// A child process started by start_child; its output is readable on `out`, the read end of a
/// pipe whose write end only the child holds.
struct Child {
  pid_t pid = -1;
  int out = -1;
};

/// How a child process ended.
struct ChildEnd {
  int status = -1;         // the status it exited with; -1 when a signal ended it
  int signal = 0;          // the signal that ended it (SIGKILL at the time limit), or 0
  bool timed_out = false;  // killed because it ran past its time limit
  bool stopped = false;    // ended by a signal after the caller's `stop` asked for it
  std::string output;      // the bytes it wrote on its output (finish_child, run_in_child)

  /// True when it exited with status 0.
  bool succeeded() const { return status == 0; }
  /// "exited with status N", "killed by signal N (name)", "ran past its time limit" or "stopped".
  std::string what() const;
};

/// Forks a child that runs f(out), `out` being the write end of the pipe to the parent, and
/// exits with f's return value by std::_Exit (no atexit handlers or static destructors run in
/// the child). Buffered stdio output is flushed first, so nothing is written twice. Throws
/// std::system_error when the pipe or the fork fails.
Child start_child(const std::function<int(int out)>& f);

/// Waits for a child to end (reaps it) and says how. `out` is left to the caller.
ChildEnd wait_child(pid_t pid);

/// Reads a child's output to the end and reaps it, closing `out`. A child still running
/// `timeout_seconds` (> 0; 0: no limit) after the call is killed with SIGKILL. When `stop` (if
/// given; asked at least every 100 ms) returns true, the child gets SIGTERM (a child may defer it
/// over what it must not leave half done), and SIGKILL if it still runs a second later.
ChildEnd finish_child(Child child, double timeout_seconds = 0, const std::function<bool()>& stop = {});

/// start_child then finish_child: f's exit status, the signal that ended it, and its output.
ChildEnd run_in_child(const std::function<int(int out)>& f, double timeout_seconds = 0,
                      const std::function<bool()>& stop = {});

/// Writes all of `bytes` to `fd` (retrying short writes and EINTR); false on an error.
bool write_all(int fd, std::string_view bytes);

}  // namespace cc::harness
