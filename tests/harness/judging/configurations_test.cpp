#include "harness/judging/configurations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace cc::harness {
namespace {

bool has(const std::vector<std::string_view>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

ExactVerdict verdict(bool hit, double margin) {
  ExactVerdict v;
  v.answer.hit = hit;
  v.margin = margin;
  return v;
}

TEST(Configurations, EveryKindHasSomeAndEveryNameIsExpectedOnlyOnce) {
  for (QueryKind kind : kAllQueryKinds) {
    const auto names = expected_configurations(kind);
    EXPECT_FALSE(names.empty()) << name(kind);
    for (std::string_view n : names) EXPECT_EQ(std::count(names.begin(), names.end(), n), 1) << name(kind) << ": " << n;
  }
}

TEST(Configurations, TouchingAndNearlyTouchingComeFromTheExactMargin) {
  const Input balls = SphereSphereInput{{{0, 0, 0}, 1}, {{2, 0, 0}, 1}};
  EXPECT_TRUE(has(configurations_of(balls, verdict(true, 0)), "touching"));
  EXPECT_TRUE(has(configurations_of(balls, verdict(false, -0x1p-45)), "just apart"));
  EXPECT_TRUE(has(configurations_of(balls, verdict(true, 0x1p-45)), "just overlapping"));
  EXPECT_TRUE(configurations_of(balls, verdict(false, -0x1p-20)).empty());
}

TEST(Configurations, FramesAtTheToleranceNearlyParallelFarAndLong) {
  const double e = 0x1p-49;
  const Mat3 stretched = Mat3::from_columns({1 + e, 0, 0}, {0, 1, 0}, {0, 0, 1});
  const double tilt = 0x1p-30;
  const Mat3 tilted = Mat3::from_columns({1, tilt, 0}, {-tilt, 1, 0}, {0, 0, 1});
  const Input boxes = ObbObbInput{{{0x1p30, 0, 0}, {1, 0x1p-25, 0}, stretched}, {{0x1p30, 3, 0}, {1, 1, 1}, tilted}};
  const auto names = configurations_of(boxes, verdict(false, -1));
  for (std::string_view n : {"frame at the tolerance", "nearly parallel axes", "far from the origin", "long box", "flat box"}) {
    EXPECT_TRUE(has(names, n)) << n;
  }
  EXPECT_FALSE(has(names, "sizes far apart"));
}

TEST(Configurations, TrianglesTheirShapesAndTheirVertexOrder) {
  const Triangle sliver{{Vec3{0, 0, 0}, Vec3{1, 0x1p-30, 0}, Vec3{0.5, 0, 0}}};
  const Aabb box{{2, -1, -1}, {3, 1, 1}};
  auto names = configurations_of(TriAabbInput{sliver, box}, verdict(false, -0.25));
  EXPECT_TRUE(has(names, "sliver"));
  EXPECT_TRUE(has(names, "in a face's plane"));  // z = 0: the plane of the box's z faces
  EXPECT_TRUE(has(names, "far vertex not last"));  // v[0] is farthest from the box's centre
  names = configurations_of(TriAabbInput{{{Vec3{1, 0, 0}, Vec3{1.5, 1, 0}, Vec3{0, 0, 0x1p-25}}}, box}, verdict(false, -0.25));
  EXPECT_FALSE(has(names, "far vertex not last"));  // v[2] is
  EXPECT_TRUE(has(names, "nearly in a face's plane") || has(names, "edge nearly parallel to an axis"));
}

TEST(Configurations, RaysFromFarAwayWithNegativeParameters) {
  ExactVerdict hit = verdict(true, 0.1);
  hit.answer.params = {-0x1p22, -0x1p22 + 1};
  const Input ray = RayAabbInput{{{0x1p22, 0.5, 0.5}, {1, 0x1p-30, 0}, -INFINITY, INFINITY}, {{0, 0, 0}, {1, 1, 1}}};
  const auto names = configurations_of(ray, hit);
  for (std::string_view n : {"from far away", "negative parameters", "nearly parallel to a slab", "parallel to a slab"}) {
    EXPECT_TRUE(has(names, n)) << n;
  }
}

}  // namespace
}  // namespace cc::harness
