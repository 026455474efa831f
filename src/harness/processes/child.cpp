#include "harness/processes/child.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <system_error>

namespace cc::harness {

std::string ChildEnd::what() const {
  if (timed_out) return "ran past its time limit";
  if (stopped) return "stopped";
  if (signal != 0) return "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
  return "exited with status " + std::to_string(status);
}

Child start_child(const std::function<int(int out)>& f) {
  int fds[2];
  if (pipe(fds) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    const int error = errno;
    ::close(fds[0]), ::close(fds[1]);
    throw std::system_error(error, std::generic_category(), "fork");
  }
  if (pid == 0) {
    ::close(fds[0]);
    std::_Exit(f(fds[1]));
  }
  ::close(fds[1]);
  return {pid, fds[0]};
}

ChildEnd wait_child(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return {};
  }
  ChildEnd end;
  if (WIFEXITED(status)) end.status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) end.signal = WTERMSIG(status);
  return end;
}

ChildEnd finish_child(Child child, double timeout_seconds, const std::function<bool()>& stop) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeout_seconds);
  std::string output;
  bool killed = false, stopped = false;
  auto stop_deadline = Clock::now();
  char chunk[65536];
  for (;;) {
    if (stop && !killed && !stopped && stop()) {
      kill(child.pid, SIGTERM);  // it may finish what it must not leave half done first
      stopped = true;
      stop_deadline = Clock::now() + std::chrono::seconds(1);
    }
    if (stopped && !killed && Clock::now() > stop_deadline) {
      kill(child.pid, SIGKILL);
      killed = true;
    }
    int wait_ms = stop && !killed ? 100 : -1;
    if (timeout_seconds > 0 && !killed && !stopped) {
      // Rounded up, so that the child is never killed before its time.
      const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) {
        kill(child.pid, SIGKILL);
        killed = true;
      } else {
        wait_ms = static_cast<int>(std::min<long long>(left, wait_ms < 0 ? 1000 : wait_ms));
      }
    }
    pollfd p{child.out, POLLIN, 0};
    const int ready = poll(&p, 1, wait_ms);
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t n = ::read(child.out, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file: the child closed its output or ended
    output.append(chunk, static_cast<std::size_t>(n));
  }
  ::close(child.out);
  ChildEnd end = wait_child(child.pid);
  end.timed_out = killed && !stopped && end.signal == SIGKILL;
  end.stopped = stopped && end.signal != 0;
  end.output = std::move(output);
  return end;
}

ChildEnd run_in_child(const std::function<int(int out)>& f, double timeout_seconds, const std::function<bool()>& stop) {
  return finish_child(start_child(f), timeout_seconds, stop);
}

bool write_all(int fd, std::string_view bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace cc::harness
