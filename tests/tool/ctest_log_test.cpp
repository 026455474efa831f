// Reading ctest's output: test times and failures from a whole log, and the test running now
// from a log read as it grows, in pieces that split lines anywhere.
#include "tool/ctest_log.h"

#include <gtest/gtest.h>

namespace cc::tool {
namespace {

const std::string kLog =
    "Test project /build\n"
    "      Start  12: corpus.ray_aabb\n"
    " 1/4 Test  #12: corpus.ray_aabb ....................   Passed    0.40 sec\n"
    "      Start 130: EveryKernel/TestRayAabbs.TouchingIsAHit/avx2\n"
    " 2/4 Test #130: EveryKernel/TestRayAabbs.TouchingIsAHit/avx2 ...   Passed   12.50 sec\n"
    "      Start 131: Simd.Kernel\n"
    " 3/4 Test #131: Simd.Kernel ...........................***Skipped   0.00 sec\n"
    "      Start   7: fuzz.obb_obb\n"
    " 4/4 Test   #7: fuzz.obb_obb ..........Subprocess aborted***Exception:   0.02 sec\n"
    "      Start   8: Slow.Test\n"
    " 5/5 Test   #8: Slow.Test ..........................***Timeout 300.01 sec\n";

TEST(CtestLog, TheTimesOfThePassedTests) {
  const auto seconds = passed_test_seconds(kLog);
  ASSERT_EQ(seconds.size(), 2u);
  EXPECT_EQ(seconds.at("corpus.ray_aabb"), 0.40);
  EXPECT_EQ(seconds.at("EveryKernel/TestRayAabbs.TouchingIsAHit/avx2"), 12.5);
}

TEST(CtestLog, TheFailedTestsButNotTheSkippedOnes) {
  const auto failed = failed_tests(kLog);
  ASSERT_EQ(failed.size(), 2u);
  EXPECT_EQ(failed[0], (std::pair<std::string, std::string>{"fuzz.obb_obb", "Exception"}));
  EXPECT_EQ(failed[1], (std::pair<std::string, std::string>{"Slow.Test", "Timeout"}));
}

TEST(RunningTest, IsTheTestStartedAndNotYetReported) {
  for (std::size_t piece : {std::size_t{1}, std::size_t{7}, kLog.size()}) {
    RunningTest running;
    std::vector<std::optional<std::string>> seen;
    for (std::size_t at = 0; at < kLog.size(); at += piece) {
      running.feed(std::string_view(kLog).substr(at, piece));
      if (seen.empty() || seen.back() != running.name()) seen.push_back(running.name());
    }
    EXPECT_EQ(running.name(), std::nullopt) << "every test was reported";
    if (piece == kLog.size()) continue;  // read whole, no test is seen running
    const std::vector<std::optional<std::string>> expected = {
        std::nullopt, "corpus.ray_aabb", std::nullopt, "EveryKernel/TestRayAabbs.TouchingIsAHit/avx2", std::nullopt,
        "Simd.Kernel", std::nullopt, "fuzz.obb_obb", std::nullopt, "Slow.Test", std::nullopt};
    EXPECT_EQ(seen, expected) << "pieces of " << piece;
  }
  RunningTest half;
  half.feed("      Start  12: corpus.ray_aabb\n 1/4 Test  #12: corpus.ray_aabb ....");  // the line is not whole yet
  EXPECT_EQ(half.name(), "corpus.ray_aabb");
}

}  // namespace
}  // namespace cc::tool
