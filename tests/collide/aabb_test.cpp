#include "collide/aabb.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cc {
namespace {

const Aabb kUnit{{0, 0, 0}, {1, 1, 1}};

TEST(TestAabbAabb, TouchingAtAFaceAnEdgeAndACornerIsContact) {
  EXPECT_TRUE(test_aabb_aabb(kUnit, {{1, 0, 0}, {2, 1, 1}}));  // face
  EXPECT_TRUE(test_aabb_aabb(kUnit, {{1, 1, 0}, {2, 2, 1}}));  // edge
  EXPECT_TRUE(test_aabb_aabb(kUnit, {{1, 1, 1}, {2, 2, 2}}));  // corner
}

TEST(TestAabbAabb, OneUlpApartIsNoContact) {
  const double next = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(test_aabb_aabb(kUnit, {{next, 0, 0}, {2, 1, 1}}));
  EXPECT_FALSE(test_aabb_aabb(kUnit, {{next, next, next}, {2, 2, 2}}));
}

TEST(TestAabbAabb, ZeroExtentBoxesTakePartAsPointsAndRectangles) {
  EXPECT_TRUE(test_aabb_aabb(kUnit, {{1, 1, 1}, {1, 1, 1}}));           // a point at a corner
  EXPECT_TRUE(test_aabb_aabb(kUnit, {{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}}));  // a point inside
  EXPECT_FALSE(test_aabb_aabb(kUnit, {{2, 0, 0}, {2, 1, 1}}));          // a rectangle apart
  EXPECT_TRUE(test_aabb_aabb({{1, 1, 1}, {1, 1, 1}}, {{1, 1, 1}, {1, 1, 1}}));  // equal points
}

TEST(TestAabbAabb, IsSymmetric) {
  const Aabb b{{0.5, -1, 1}, {3, 0, 2}};
  EXPECT_EQ(test_aabb_aabb(kUnit, b), test_aabb_aabb(b, kUnit));
  EXPECT_TRUE(test_aabb_aabb(kUnit, b));
}

TEST(TestAabbAabb, NanIsNoContactAndInfinitiesAreExtendedReals) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(test_aabb_aabb(kUnit, {{nan, 0, 0}, {1, 1, 1}}));
  EXPECT_FALSE(test_aabb_aabb(kUnit, {{0, 0, 0}, {1, nan, 1}}));
  EXPECT_TRUE(test_aabb_aabb(kUnit, {{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}}));
  EXPECT_FALSE(test_aabb_aabb(kUnit, {{2, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}}));
}

TEST(TestAabbAabb, AnInvertedBoxIsComparedAxisByAxis) {
  // Out of contract: lo > hi on x. The documented answer is the per-axis comparison.
  const Aabb inverted{{0.75, 0, 0}, {0.25, 1, 1}};
  EXPECT_TRUE(test_aabb_aabb(kUnit, inverted));
  const Aabb empty{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  EXPECT_FALSE(test_aabb_aabb(kUnit, empty));
}

}  // namespace
}  // namespace cc
