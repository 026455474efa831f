// Running a function, or a program, in a child process: the one place where the project forks
// and waits. A crash, a hang or a damaged heap in the child (a peer library's, a user's code, a
// build) costs the child, never the caller. Both kinds of child end the same way (finish_child:
// the time limit, the kill, the exit status or signal, the output bytes); they differ in how
// they start: a function runs in a fork of the caller, a program is spawned and runs nothing of
// the caller's.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cc::harness {

/// A child process started by start_child or start_program; its output is readable on `out`,
/// the read end of a pipe whose write end only the child holds (-1: its output goes to files).
struct Child {
  pid_t pid = -1;
  int out = -1;
  bool group = false;  // it leads its own process group: a kill reaches whatever it started too
};

/// How a child process ended.
struct ChildEnd {
  int status = -1;         // the status it exited with; -1 when a signal ended it
  int signal = 0;          // the signal that ended it (SIGKILL at the time limit), or 0
  bool timed_out = false;  // killed because it ran past its time limit
  bool stopped = false;    // ended by a signal after finish_child's `stop` asked for it
  std::string output;      // the bytes it wrote on its output (finish_child, run_in_child)

  /// True when it exited with status 0.
  bool succeeded() const { return status == 0; }
  /// "exited with status N", "killed by signal N (name)", "timed out: ran past its time limit"
  /// (harness::is_time_out) or "was stopped".
  std::string what() const;
};

/// The exit status of a child whose function threw (a C++ exception never leaves the child).
inline constexpr int kChildThrew = 70;

/// Whether a child started by start_child stays in the caller's process group, or leads one of
/// its own, so that finish_child's signals reach the processes it starts too (none is left
/// running when it is stopped) and a terminal's Ctrl-C does not.
enum class ChildGroup { callers, own };

/// Forks a child that runs f(out), `out` being the write end of the pipe to the parent, and
/// exits with f's return value by std::_Exit (no atexit handlers or static destructors run in
/// the child), or with kChildThrew when f throws. Buffered stdio output is flushed first, so
/// nothing is written twice. Throws std::system_error when the pipe or the fork fails.
Child start_child(const std::function<int(int out)>& f, ChildGroup group = ChildGroup::callers);

/// Waits for a child to end (reaps it) and says how. `out` is left to the caller.
ChildEnd wait_child(pid_t pid);

/// Where a program started by start_program runs and where its output goes. Relative paths are
/// the caller's (the files are opened before the program changes folder).
struct ProgramIo {
  std::filesystem::path cwd;  // its working folder; empty: the caller's
  std::filesystem::path out;  // stdout appended to this file (made if missing); empty: a pipe to
                              // the caller, read into ChildEnd::output
  std::filesystem::path err;  // stderr appended to this file; empty: where stdout goes
};

/// Starts the program argv[0] (looked up in PATH) with the arguments argv, stdin /dev/null, in
/// its own process group (so that finish_child's kill reaches the processes it starts, and a
/// terminal's Ctrl-C reaches only the caller). Unlike start_child it runs nothing of the
/// caller's: posix_spawn makes the child, which only arranges its files and execs, so any
/// thread may call this while others run (the pipe is close-on-exec, so no other program
/// spawned meanwhile holds it). Throws std::system_error when the pipe fails or the program
/// cannot be started (not found, not executable, a file that cannot be opened).
Child start_program(const std::vector<std::string>& argv, const ProgramIo& io = {});

/// Reads a child's output to the end (if it has a pipe) and reaps it, closing `out`. A child
/// still running `timeout_seconds` (> 0; 0: no limit) after the call is killed with SIGKILL. When
/// `stop`, asked at least every 50 ms while it runs, returns true, the child gets SIGTERM (a child
/// may defer it over what it must not leave half done), and SIGKILL if it still runs a second
/// later. Signals reach its whole process group if it leads one. A child that exits by itself
/// just before its kill ends as it exited (neither timed out nor stopped).
ChildEnd finish_child(Child child, double timeout_seconds = 0, const std::function<bool()>& stop = {});

/// start_child then finish_child: f's exit status, the signal that ended it, and its output.
ChildEnd run_in_child(const std::function<int(int out)>& f, double timeout_seconds = 0,
                      const std::function<bool()>& stop = {}, ChildGroup group = ChildGroup::callers);

/// start_program then finish_child.
ChildEnd run_program(const std::vector<std::string>& argv, const ProgramIo& io = {}, double timeout_seconds = 0,
                     const std::function<bool()>& stop = {});

/// Points the descriptor `fd` (standard output or error) at a new unnamed temporary file, so
/// that what a party prints there can be looked at (take_captured_line); false when it cannot.
bool capture_to_file(int fd);

/// The first line written to the file `fd` since it was last emptied (at most 200 bytes, control
/// characters as spaces, bytes beyond ASCII as '?'), the file emptied again; nothing when nothing was written (or `fd` is
/// no file).
std::optional<std::string> take_captured_line(int fd);

}  // namespace cc::harness
