// Running a function or a program in a child process: its exit status, the signal that ended it,
// its output (also more than a pipe holds), its time limit and its stop; a program's files,
// folder and process group, and programs started from several threads at once.
#include "harness/processes/child.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "harness/formats/write_all.h"
#include "../../temp_folder.h"
#include "harness/model/answer.h"

namespace cc::harness {
namespace {

TEST(Child, GivesItsExitStatusAndItsOutput) {
  const ChildEnd end = run_in_child([](int out) { return write_all(out, "42 apples") ? 7 : 1; });
  EXPECT_EQ(end.status, 7);
  EXPECT_EQ(end.signal, 0);
  EXPECT_FALSE(end.timed_out);
  EXPECT_FALSE(end.succeeded());
  EXPECT_EQ(end.output, "42 apples");
  EXPECT_EQ(end.what(), "exited with status 7");
  EXPECT_TRUE(run_in_child([](int) { return 0; }).succeeded());
}

// Every way a child can end, and what its parent is told: the status, the signal, the flags and
// the one line a finding records. One row per way.
struct EndingRow {
  const char* how;
  std::function<int(int)> body;
  double timeout;
  int status, signal;
  bool timed_out, succeeded;
  const char* what;
};

TEST(Child, EveryWayToEndIsToldAsItHappened) {
  const EndingRow rows[] = {
      {"returns 0", [](int) { return 0; }, 0, 0, 0, false, true, "exited with status 0"},
      {"returns 9", [](int) { return 9; }, 0, 9, 0, false, false, "exited with status 9"},
      {"returns 255", [](int) { return 255; }, 0, 255, 0, false, false, "exited with status 255"},
      {"throws", [](int) -> int { throw std::runtime_error("x"); }, 0, kChildThrew, 0, false, false, "exited with status 70"},
      {"throws no exception type", [](int) -> int { throw 3; }, 0, kChildThrew, 0, false, false, "exited with status 70"},
      {"exit(4)", [](int) -> int { std::exit(4); }, 0, 4, 0, false, false, "exited with status 4"},
      {"_Exit(0) early", [](int) -> int { std::_Exit(0); }, 0, 0, 0, false, true, "exited with status 0"},
      {"abort()", [](int) -> int { std::abort(); }, 0, -1, SIGABRT, false, false, "killed by signal 6 (Aborted)"},
      {"SIGSEGV", [](int) { return std::raise(SIGSEGV); }, 0, -1, SIGSEGV, false, false, "killed by signal 11 (Segmentation fault)"},
      {"SIGBUS", [](int) { return std::raise(SIGBUS); }, 0, -1, SIGBUS, false, false, "killed by signal 7 (Bus error)"},
      {"SIGFPE", [](int) { return std::raise(SIGFPE); }, 0, -1, SIGFPE, false, false, "killed by signal 8 (Floating point exception)"},
      {"SIGILL", [](int) { return std::raise(SIGILL); }, 0, -1, SIGILL, false, false, "killed by signal 4 (Illegal instruction)"},
      {"SIGKILL", [](int) { return std::raise(SIGKILL); }, 0, -1, SIGKILL, false, false, "killed by signal 9 (Killed)"},
      {"SIGTERM", [](int) { return std::raise(SIGTERM); }, 0, -1, SIGTERM, false, false, "killed by signal 15 (Terminated)"},
      {"SIGPIPE on a closed pipe", [](int out) { ::close(out); int p[2]; (void)!::pipe(p); ::close(p[0]); return write_all(p[1], "x") ? 0 : 1; },
       0, -1, SIGPIPE, false, false, "killed by signal 13 (Broken pipe)"},
      {"runs past its limit", [](int) { for (;;) pause(); return 0; }, 0.1, -1, SIGKILL, true, false, "timed out: ran past its time limit"},
  };
  for (const EndingRow& row : rows) {
    const ChildEnd end = run_in_child(row.body, row.timeout);
    EXPECT_EQ(end.status, row.status) << row.how;
    EXPECT_EQ(end.signal, row.signal) << row.how;
    EXPECT_EQ(end.timed_out, row.timed_out) << row.how;
    EXPECT_FALSE(end.stopped) << row.how;
    EXPECT_EQ(end.succeeded(), row.succeeded) << row.how;
    EXPECT_EQ(end.what(), row.what) << row.how;
    EXPECT_EQ(is_time_out(end.what()), row.timed_out) << row.how;
  }
}

TEST(Child, ReadsMoreOutputThanAPipeHolds) {
  const std::string big(1 << 20, 'x');
  const ChildEnd end = run_in_child([&big](int out) { return write_all(out, big) ? 0 : 1; });
  EXPECT_TRUE(end.succeeded());
  EXPECT_EQ(end.output.size(), big.size());
}

TEST(Child, ACrashIsTheChildsNotTheCallers) {
  const ChildEnd end = run_in_child([](int out) {
    write_all(out, "before");
    std::raise(SIGSEGV);
    return 0;
  });
  EXPECT_EQ(end.status, -1);
  EXPECT_EQ(end.signal, SIGSEGV);
  EXPECT_FALSE(end.timed_out);
  EXPECT_EQ(end.output, "before");
  EXPECT_NE(end.what().find("signal 11"), std::string::npos) << end.what();
}

TEST(Child, AChildPastItsTimeLimitIsKilled) {
  const auto start = std::chrono::steady_clock::now();
  const ChildEnd end = run_in_child([](int) {
    for (;;) pause();
    return 0;
  }, 0.2);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(end.timed_out);
  EXPECT_EQ(end.signal, SIGKILL);
  EXPECT_GE(seconds, 0.2);
  EXPECT_LT(seconds, 10.0);
  EXPECT_EQ(end.what(), "timed out: ran past its time limit");
}

// A child in a group of its own is stopped with the children it started: none is left running.
// (Its grandchild's pid comes back through a pipe of the test's, as the child is busy.)
TEST(Child, AChildInItsOwnGroupIsStoppedWithWhatItStarted) {
  int pids[2];
  ASSERT_EQ(::pipe(pids), 0);
  const auto start = std::chrono::steady_clock::now();
  bool asked = false;
  const ChildEnd end = run_in_child(
      [&](int) {
        const pid_t grandchild = ::fork();
        if (grandchild == 0) {
          for (;;) pause();
        }
        (void)!::write(pids[1], &grandchild, sizeof grandchild);
        for (;;) pause();
        return 0;
      },
      0,
      [&] {
        const bool stop = asked;
        asked = true;  // stopped at the second question, 50 ms in
        return stop;
      },
      ChildGroup::own);
  pid_t grandchild = 0;
  ASSERT_EQ(::read(pids[0], &grandchild, sizeof grandchild), static_cast<ssize_t>(sizeof grandchild));
  ::close(pids[0]), ::close(pids[1]);
  EXPECT_TRUE(end.stopped);
  EXPECT_EQ(end.signal, SIGTERM);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  // The grandchild got the SIGTERM too: it is gone, or a zombie about to be reaped.
  for (int tries = 0; tries < 100 && ::kill(grandchild, 0) == 0; ++tries) {
    std::ifstream stat("/proc/" + std::to_string(grandchild) + "/stat");
    std::string pid, name, state;
    if (!(stat >> pid >> name >> state) || state == "Z") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::ifstream stat("/proc/" + std::to_string(grandchild) + "/stat");
  std::string pid, name, state;
  EXPECT_TRUE(!(stat >> pid >> name >> state) || state == "Z") << "the grandchild still runs: " << state;
}

TEST(Child, StartedChildrenAreReapedOneByOne) {
  const Child a = start_child([](int out) { return write_all(out, "a") ? 3 : 1; });
  const Child b = start_child([](int out) { return write_all(out, "b") ? 4 : 1; });
  const ChildEnd end_b = finish_child(b), end_a = finish_child(a);
  EXPECT_EQ(end_a.status, 3);
  EXPECT_EQ(end_a.output, "a");
  EXPECT_EQ(end_b.status, 4);
  EXPECT_EQ(end_b.output, "b");
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Program, GivesItsExitStatusAndItsOutputBytes) {
  const ChildEnd end = run_program({"sh", "-c", "printf 'a\\000b\\377'; echo to-stderr >&2; exit 3"});
  EXPECT_EQ(end.status, 3);
  EXPECT_EQ(end.signal, 0);
  EXPECT_FALSE(end.timed_out);
  EXPECT_FALSE(end.stopped);
  EXPECT_EQ(end.output, std::string("a\0b\377", 4) + "to-stderr\n");  // stderr goes where stdout goes
  EXPECT_EQ(end.what(), "exited with status 3");
  EXPECT_TRUE(run_program({"true"}).succeeded());
}

TEST(Program, ReadsMoreOutputThanAPipeHolds) {
  const ChildEnd end = run_program({"head", "-c", "1048576", "/dev/zero"});
  EXPECT_TRUE(end.succeeded());
  EXPECT_EQ(end.output, std::string(1 << 20, '\0'));
}

TEST(Program, ASignalEndsIt) {
  const ChildEnd end = run_program({"sh", "-c", "kill -SEGV $$"});
  EXPECT_EQ(end.status, -1);
  EXPECT_EQ(end.signal, SIGSEGV);
  EXPECT_FALSE(end.timed_out);
}

// The time limit kills the program's whole group: were the background sleep left alive, it would
// hold the pipe open for 30 s.
TEST(Program, AProgramPastItsTimeLimitIsKilledWithWhatItStarted) {
  const auto start = std::chrono::steady_clock::now();
  const ChildEnd end = run_program({"sh", "-c", "sleep 30 & wait"}, {}, 0.2);
  const double seconds = seconds_since(start);
  EXPECT_TRUE(end.timed_out);
  EXPECT_EQ(end.signal, SIGKILL);
  EXPECT_GE(seconds, 0.2);
  EXPECT_LT(seconds, 10.0);
  EXPECT_EQ(end.what(), "timed out: ran past its time limit");
}

TEST(Program, StopKillsItWithoutAPipeToo) {
  const cc::test::TempFolder folder("child_stop");
  int asked = 0;
  const auto start = std::chrono::steady_clock::now();
  ProgramIo to_a_file;
  to_a_file.out = folder.path() / "log";
  const ChildEnd end = run_program({"sleep", "30"}, to_a_file, 0, [&asked] { return ++asked == 3; });
  EXPECT_LT(seconds_since(start), 10.0);
  EXPECT_EQ(asked, 3);
  EXPECT_TRUE(end.stopped);
  EXPECT_FALSE(end.timed_out);
  EXPECT_EQ(end.signal, SIGTERM);  // asked first; sleep does not defer it
  EXPECT_EQ(end.what(), "was stopped");
}

// Without a pipe to wait on, the parent looks for the program's end now and then: it does not
// spin while the program runs (a spinning parent spends the program's 0.3 s on the processor).
TEST(Program, AProgramWithoutAPipeIsWaitedForWithoutSpinning) {
  const cc::test::TempFolder folder("child_nap");
  ProgramIo to_a_file;
  to_a_file.out = folder.path() / "log";
  const auto cpu_seconds = [] {
    timespec t{};
    ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  };
  const double cpu_before = cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  const ChildEnd end = run_program({"sleep", "0.3"}, to_a_file, 5);
  EXPECT_TRUE(end.succeeded()) << end.what();
  EXPECT_GE(seconds_since(start), 0.3);
  EXPECT_LT(cpu_seconds() - cpu_before, 0.1);
}

// A program that defers SIGTERM (as a child storing a case file does) gets SIGKILL a second later,
// it and what it started.
TEST(Program, StopKillsAProgramThatIgnoresSigtermASecondLater) {
  const auto start = std::chrono::steady_clock::now();
  // Stopped once the shell has had half a second to set its trap.
  const auto stop = [&start] { return seconds_since(start) > 0.5; };
  const ChildEnd end = run_program({"sh", "-c", "trap '' TERM; sleep 30 & wait"}, {}, 0, stop);
  const double seconds = seconds_since(start);
  EXPECT_TRUE(end.stopped);
  EXPECT_EQ(end.signal, SIGKILL);
  EXPECT_GE(seconds, 1.5);
  EXPECT_LT(seconds, 10.0);
}

TEST(Program, AppendsToItsFilesInItsFolder) {
  const cc::test::TempFolder folder("child_files");
  const auto out = folder.path() / "out.log", err = folder.path() / "err.log";
  std::ofstream(out) << "before\n";
  std::filesystem::create_directory(folder.path() / "work");
  const ChildEnd end = run_program({"sh", "-c", "pwd; echo oops >&2; cat"}, {folder.path() / "work", out, err}, 10);
  EXPECT_TRUE(end.succeeded()) << end.what();
  EXPECT_EQ(end.output, "");
  // stdin is /dev/null: cat reads nothing and ends.
  EXPECT_EQ(file_text(out), "before\n" + std::filesystem::canonical(folder.path() / "work").string() + "\n");
  EXPECT_EQ(file_text(err), "oops\n");
}

TEST(Program, OneThatCannotStartThrows) {
  EXPECT_THROW(run_program({"no-such-program-anywhere"}), std::system_error);
  const cc::test::TempFolder folder("child_cannot_open");
  ProgramIo nowhere;
  nowhere.out = folder.path() / "missing" / "log";
  EXPECT_THROW(run_program({"true"}, nowhere), std::system_error);
}

// Programs spawned from other threads meanwhile must not hold this one's pipe (or its output
// would end only when they do): the caller's end is close-on-exec, as was the child's end.
TEST(Program, ItsPipeIsNotHandedToOtherPrograms) {
  const Child child = start_program({"true"});
  ASSERT_GE(child.out, 0);
  EXPECT_TRUE(child.group);
  EXPECT_NE(fcntl(child.out, F_GETFD) & FD_CLOEXEC, 0);
  EXPECT_TRUE(finish_child(child).succeeded());
}

TEST(Program, ProgramsRunFromSeveralThreadsAtOnce) {
  std::vector<std::thread> threads;
  std::vector<std::vector<ChildEnd>> ends(4);
  for (std::size_t i = 0; i < ends.size(); ++i) {
    threads.emplace_back([&ends, i] {
      for (int run = 0; run < 10; ++run) ends[i].push_back(run_program({"sh", "-c", "echo " + std::to_string(i)}, {}, 60));
    });
  }
  for (std::thread& t : threads) t.join();
  for (std::size_t i = 0; i < ends.size(); ++i) {
    for (const ChildEnd& end : ends[i]) {
      EXPECT_TRUE(end.succeeded()) << end.what();
      EXPECT_EQ(end.output, std::to_string(i) + "\n");
    }
  }
}

}  // namespace
}  // namespace cc::harness
