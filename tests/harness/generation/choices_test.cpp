#include "harness/generation/choices.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>


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

TEST(MixSeed, SpreadsNearbySeeds) {
  std::set<std::uint64_t> seeds;
  for (std::uint64_t i = 0; i < 1000; ++i) seeds.insert(mix_seed(1, i));
  EXPECT_EQ(seeds.size(), 1000u);
}

}  // namespace
}  // namespace cc::harness
