#include "harness/processes/child.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <thread>

extern char** environ;

namespace cc::harness {

std::string ChildEnd::what() const {
  if (timed_out) return "timed out: ran past its time limit";
  if (stopped) return "was stopped";
  if (signal != 0) return "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
  return "exited with status " + std::to_string(status);
}

Child start_child(const std::function<int(int out)>& f, ChildGroup group) {
  int fds[2];
  if (pipe(fds) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    const int error = errno;
    ::close(fds[0]), ::close(fds[1]);
    throw std::system_error(error, std::generic_category(), "fork");
  }
  const bool own = group == ChildGroup::own;
  if (pid == 0) {
    if (own) ::setpgid(0, 0);
    ::close(fds[0]);
    int status = kChildThrew;
    try {
      status = f(fds[1]);
    } catch (...) {  // never unwinds into the parent's code: the child ends here
    }
    std::_Exit(status);
  }
  if (own) ::setpgid(pid, pid);  // here too: the group exists before any signal is sent to it
  ::close(fds[1]);
  return {pid, fds[0], own};
}

namespace {

// How often finish_child asks `stop`, and at most how long it waits between looks for the end of a
// child without a pipe.
constexpr int kPollMs = 50;

// Reaps pid: its end once it has ended (waiting for it when `block`), nothing while it runs.
std::optional<ChildEnd> reap(pid_t pid, bool block) {
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &status, block ? 0 : WNOHANG);
    if (done == pid) break;
    if (done == 0) return std::nullopt;
    if (errno != EINTR) return ChildEnd{};  // not a child of ours (any more): no status to give
  }
  ChildEnd end;
  if (WIFEXITED(status)) end.status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) end.signal = WTERMSIG(status);
  return end;
}

}  // namespace

Child start_program(const std::vector<std::string>& argv, const ProgramIo& io) {
  if (argv.empty()) throw std::invalid_argument("start_program: no program");
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  int fds[2] = {-1, -1};
  if (io.out.empty() && pipe2(fds, O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category(), "pipe");

  // The child's files, in order: stdin, stdout, stderr, then its folder (so that relative paths
  // are the caller's). dup2 onto stdout clears close-on-exec on that copy alone.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  const std::string out = io.out.string(), err = io.err.string(), cwd = io.cwd.string();
  if (out.empty()) {
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  } else {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  }
  if (err.empty()) {
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  } else {
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  }
  if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attr, 0);  // its own group

  pid_t pid = -1;
  const int error = posix_spawnp(&pid, args[0], &actions, &attr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (fds[1] >= 0) ::close(fds[1]);
  if (error != 0) {
    if (fds[0] >= 0) ::close(fds[0]);
    throw std::system_error(error, std::generic_category(), "cannot start " + argv[0]);
  }
  return {pid, fds[0], true};
}

ChildEnd wait_child(pid_t pid) { return *reap(pid, true); }

ChildEnd finish_child(Child child, double timeout_seconds, const std::function<bool()>& stop) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeout_seconds);
  const pid_t target = child.group ? -child.pid : child.pid;  // its whole group when it leads one
  enum class Killed { no, at_time_limit, stopped } killed = Killed::no;
  bool sigkill_sent = false;
  auto stop_deadline = Clock::now();
  std::string output;
  char chunk[65536];
  std::optional<ChildEnd> end;
  int nap_ms = 1;  // without a pipe, the first looks come soon, then every kPollMs
  while (!end) {
    int wait_ms = -1;  // until the child writes or ends
    if (killed == Killed::no) {
      if (stop && stop()) {
        killed = Killed::stopped;
        kill(target, SIGTERM);  // it may finish what it must not leave half done first
        stop_deadline = Clock::now() + std::chrono::seconds(1);
      } else if (timeout_seconds > 0) {
        // Rounded up, so that the child is never killed before its time.
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) {
          killed = Killed::at_time_limit;
          kill(target, SIGKILL);
          sigkill_sent = true;
        }
        wait_ms = static_cast<int>(std::clamp<long long>(left, 0, 1000));
      }
      if (killed == Killed::no && stop) wait_ms = wait_ms < 0 ? kPollMs : std::min(wait_ms, kPollMs);
    }
    if (killed == Killed::stopped && !sigkill_sent) {  // a second after SIGTERM: SIGKILL
      const auto left = std::chrono::ceil<std::chrono::milliseconds>(stop_deadline - Clock::now()).count();
      if (left <= 0) {
        kill(target, SIGKILL);
        sigkill_sent = true;
      }
      wait_ms = static_cast<int>(std::clamp<long long>(left, 0, kPollMs));
    }
    if (sigkill_sent) wait_ms = -1;
    if (child.out >= 0) {
      pollfd p{child.out, POLLIN, 0};
      const int ready = poll(&p, 1, wait_ms);
      if (ready == 0 || (ready < 0 && errno == EINTR)) continue;
      const ssize_t n = ready < 0 ? -1 : ::read(child.out, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n > 0) {
        output.append(chunk, static_cast<std::size_t>(n));
      } else {  // end of file (the child closed its output or ended), or an error
        ::close(child.out);
        child.out = -1;
      }
    } else if (wait_ms < 0) {
      end = reap(child.pid, true);
    } else if (!(end = reap(child.pid, false))) {
      std::this_thread::sleep_for(std::chrono::milliseconds(std::min(wait_ms, nap_ms)));
      nap_ms = std::min(2 * nap_ms, kPollMs);  // a child about to end is not waited for 50 ms
    }
  }
  end->timed_out = killed == Killed::at_time_limit && end->signal == SIGKILL;
  end->stopped = killed == Killed::stopped && end->signal != 0;
  end->output = std::move(output);
  return *end;
}

ChildEnd run_in_child(const std::function<int(int out)>& f, double timeout_seconds, const std::function<bool()>& stop,
                      ChildGroup group) {
  return finish_child(start_child(f, group), timeout_seconds, stop);
}

ChildEnd run_program(const std::vector<std::string>& argv, const ProgramIo& io, double timeout_seconds,
                     const std::function<bool()>& stop) {
  return finish_child(start_program(argv, io), timeout_seconds, stop);
}

bool capture_to_file(int fd) {
  std::FILE* file = std::tmpfile();
  if (file == nullptr) return false;
  const int copy = ::dup(::fileno(file));
  std::fclose(file);
  if (copy < 0 || ::dup2(copy, fd) < 0) return false;
  ::close(copy);
  return true;
}

std::optional<std::string> take_captured_line(int fd) {
  if (::lseek(fd, 0, SEEK_END) <= 0) return std::nullopt;
  char line[201] = {};
  const ssize_t n = ::pread(fd, line, sizeof line - 1, 0);
  if (::ftruncate(fd, 0) != 0 || ::lseek(fd, 0, SEEK_SET) != 0) return "(unreadable)";
  std::string text(line, n > 0 ? static_cast<std::size_t>(n) : 0);
  text = text.substr(0, text.find('\n'));
  for (char& ch : text) {  // printable ASCII only: it is shown, and stored in JSON
    const auto byte = static_cast<unsigned char>(ch);
    if (byte < 0x20 || byte == 0x7f) ch = ' ';
    if (byte > 0x7f) ch = '?';
  }
  return text;
}

}  // namespace cc::harness
