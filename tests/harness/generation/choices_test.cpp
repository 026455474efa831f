#include "harness/generation/choices.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "harness/generation/values.h"

namespace cc::harness {
namespace {

TEST(RandomChoices, AreDeterministicAndInRange) {
  RandomChoices a(42), b(42);
  for (int i = 0; i < 1000; ++i) {
    const auto x = a.draw(7);
    EXPECT_EQ(x, b.draw(7));
    EXPECT_LT(x, 7u);
  }
}

TEST(ReplayChoices, ReplaysModuloAndThenGivesZeros) {
  const std::vector<std::uint64_t> recorded = {3, 10, 5};
  ReplayChoices c(recorded);
  EXPECT_EQ(c.draw(100), 3u);
  EXPECT_EQ(c.draw(4), 2u);
  EXPECT_EQ(c.draw(100), 5u);
  EXPECT_EQ(c.draw(100), 0u);
}

TEST(ValueSource, ZeroChoicesGiveTheSimplestValue) {
  ReplayChoices zeros({});
  ValueSource v(zeros, {});
  EXPECT_EQ(v.coordinate(), 0.0);
  EXPECT_EQ(v.length(), 0.0);
}

TEST(ValueSource, MeetsTheBoundaryValues) {
  RandomChoices c(1);
  ValueSource v(c, {8, true, true, true});
  bool zero = false, neg_zero = false, subnormal = false, nan = false, inf = false, huge = false, repeated = false;
  std::set<double> seen;
  for (int i = 0; i < 20000; ++i) {
    const double x = v.coordinate();
    zero |= x == 0 && !std::signbit(x);
    neg_zero |= x == 0 && std::signbit(x);
    subnormal |= std::fpclassify(x) == FP_SUBNORMAL;
    nan |= std::isnan(x);
    inf |= std::isinf(x);
    huge |= std::isfinite(x) && std::fabs(x) > 0x1p100;
    if (std::isfinite(x) && x != 0 && !seen.insert(x).second) repeated = true;
  }
  EXPECT_TRUE(zero && neg_zero && subnormal && nan && inf && huge && repeated);
}

TEST(MixSeed, SpreadsNearbySeeds) {
  std::set<std::uint64_t> seeds;
  for (std::uint64_t i = 0; i < 1000; ++i) seeds.insert(mix_seed(1, i));
  EXPECT_EQ(seeds.size(), 1000u);
}

}  // namespace
}  // namespace cc::harness
