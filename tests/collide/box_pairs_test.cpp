#include "collide/box_pairs.h"

#include <gtest/gtest.h>

#include <random>

namespace cc {
namespace {

TEST(SortAndSweep, TouchingZeroExtentIdenticalAndNestedBoxes) {
  const std::vector<Aabb> boxes{
      {{0, 0, 0}, {1, 1, 1}},
      {{1, 0, 0}, {2, 1, 1}},        // touches 0 at x = 1
      {{0, 0, 0}, {1, 1, 1}},        // identical to 0
      {{0.25, 0.25, 0.25}, {0.5, 0.5, 0.5}},  // inside 0
      {{3, 3, 3}, {3, 3, 3}},        // a point, alone
      {{2, 1, 1}, {2, 1, 1}},        // a point on box 1's corner
      {{0, 2, 0}, {1, 3, 1}},        // apart along y only
  };
  const std::vector<ObjectPair> expected{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 5}, {2, 3}};
  EXPECT_EQ(sort_and_sweep(boxes), expected);
  EXPECT_EQ(box_pairs_brute_force(boxes), expected);
}

TEST(SortAndSweep, NanBoxesOverlapNothing) {
  const std::vector<Aabb> boxes{{{0, 0, 0}, {1, 1, 1}}, {{NAN, 0, 0}, {1, 1, 1}}, {{0, 0, 0}, {1, NAN, 1}}};
  EXPECT_TRUE(sort_and_sweep(boxes).empty());
  EXPECT_TRUE(box_pairs_brute_force(boxes).empty());
}

TEST(SortAndSweep, AgreesWithBruteForceOnSnappedRandomBoxes) {
  std::mt19937_64 random(3);
  std::uniform_int_distribution<int> grid(0, 8);  // few values: many equal endpoints
  for (int round = 0; round < 50; ++round) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 60; ++i) {
      Aabb b;
      for (int k = 0; k < 3; ++k) {
        const int a = grid(random), c = grid(random);
        b.lo[k] = std::min(a, c), b.hi[k] = std::max(a, c);
      }
      boxes.push_back(b);
    }
    EXPECT_EQ(sort_and_sweep(boxes), box_pairs_brute_force(boxes)) << "round " << round;
  }
}

}  // namespace
}  // namespace cc
