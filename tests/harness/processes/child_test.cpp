// Running a function in a child process: its exit status, the signal that ended it, its output
// (also more than a pipe holds), and its time limit.
#include "harness/processes/child.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <csignal>

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
  EXPECT_EQ(end.what(), "ran past its time limit");
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

}  // namespace
}  // namespace cc::harness
