#include "collide/ray_aabb.h"

#include "collide/bound_records.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cc {
namespace {

const Aabb kBox{{0, 0, 0}, {1, 1, 1}};
const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kDenormMin = std::numeric_limits<double>::denorm_min();

Ray ray(Vec3 o, Vec3 d, double tmin = 0, double tmax = INFINITY) { return {o, d, tmin, tmax}; }

void expect_hit(const RayHit& h, double enter, double exit) {
  EXPECT_TRUE(h.hit);
  EXPECT_EQ(h.t_enter, enter);
  EXPECT_EQ(h.t_exit, exit);
}

TEST(IntersectRayAabb, ParallelToASlabWithTheOriginInside) {
  expect_hit(intersect_ray_aabb(ray({0.5, -1, 0.5}, {0, 1, 0}), kBox), 1, 2);
}

TEST(IntersectRayAabb, ParallelWithTheOriginExactlyOnTheBoundary) {
  for (double dx : {0.0, -0.0, kDenormMin, -kDenormMin}) {  // zero, -0, reciprocal overflows
    expect_hit(intersect_ray_aabb(ray({1, -1, 0.5}, {dx, 1, 0}), kBox), 1, 2);
    expect_hit(intersect_ray_aabb(ray({0, -1, 0.5}, {dx, 1, 0}), kBox), 1, 2);
  }
}

TEST(IntersectRayAabb, ParallelWithTheOriginJustOutside) {
  const double outside = std::nextafter(1.0, 2.0);
  for (double dx : {0.0, -0.0, kDenormMin, -kDenormMin}) {
    EXPECT_FALSE(intersect_ray_aabb(ray({outside, -1, 0.5}, {dx, 1, 0}), kBox).hit);
    EXPECT_FALSE(intersect_ray_aabb(ray({-kDenormMin, -1, 0.5}, {dx, 1, 0}), kBox).hit);
  }
}

TEST(IntersectRayAabb, ASubnormalComponentWithAFiniteReciprocalIsNotParallel) {
  // 2^-1023 is subnormal but 1/2^-1023 = 2^1023 is finite: the ray moves along x, slowly. From
  // x = 0.5 it stays inside the slab until t = 0.5 * 2^1023.
  const RayHit h = intersect_ray_aabb(ray({0.5, 0.5, 0.5}, {0x1p-1023, 0, 0}), kBox);
  EXPECT_TRUE(h.hit);
  EXPECT_EQ(h.t_enter, 0);
  EXPECT_EQ(h.t_exit, 0x1p1022);
}

TEST(IntersectRayAabb, ASegmentWithASubnormalComponentEndsWhereTmaxSays) {
  // A component of 2^-1023 is subnormal once the direction is scaled: the ray takes the full
  // test, not the inline miss decision, and its end must still count there.
  const Vec3 dir{1, 0x1p-1023, 0};
  bounds::Records records;
  EXPECT_FALSE(intersect_ray_aabb(ray({-1, 0.5, 0.5}, dir, 0, 0.9999999), kBox).hit);
  EXPECT_FALSE(intersect_ray_aabb(ray({-1, 0.5, 0.5}, dir, 0, 0.9999999), kBox, records).hit);
  expect_hit(intersect_ray_aabb(ray({-1, 0.5, 0.5}, dir, 0, 1), kBox), 1, 1);
  expect_hit(intersect_ray_aabb(ray({-1, 0.5, 0.5}, dir, 0, 1), kBox, records), 1, 1);
}

TEST(IntersectRayAabb, ARayStartingInsideEntersAtTmin) {
  expect_hit(intersect_ray_aabb(ray({0.5, 0.5, 0.5}, {1, 0, 0}), kBox), 0, 0.5);
  expect_hit(intersect_ray_aabb(ray({0.5, 0.5, 0.5}, {-2, 0, 0}), kBox), 0, 0.25);
}

TEST(IntersectRayAabb, TmaxZeroTestsTheOriginAlone) {
  expect_hit(intersect_ray_aabb(ray({0.5, 0.5, 0.5}, {1, 1, 1}, 0, 0), kBox), 0, 0);
  expect_hit(intersect_ray_aabb(ray({1, 0.5, 0.5}, {1, 1, 1}, 0, 0), kBox), 0, 0);  // on a face
  EXPECT_FALSE(intersect_ray_aabb(ray({-0.5, 0.5, 0.5}, {1, 0, 0}, 0, 0), kBox).hit);
}

TEST(IntersectRayAabb, ASegmentEndingExactlyOnAFaceTouchesIt) {
  expect_hit(intersect_ray_aabb(ray({-1, 0.5, 0.5}, {1, 0, 0}, 0, 1), kBox), 1, 1);
  EXPECT_FALSE(intersect_ray_aabb(ray({-1, 0.5, 0.5}, {1, 0, 0}, 0, 0.9999999), kBox).hit);
}

TEST(IntersectRayAabb, GrazingAnEdgeAndACorner) {
  expect_hit(intersect_ray_aabb(ray({-1, 1, 1}, {1, 0, 0}), kBox), 1, 2);  // along an edge
  expect_hit(intersect_ray_aabb(ray({-1, 1, 0.5}, {1, -1, 0}), kBox), 1, 1);  // one point of an edge
  expect_hit(intersect_ray_aabb(ray({-1, -1, -1}, {1, 1, 1}), kBox), 1, 2);  // corner to corner
  EXPECT_FALSE(intersect_ray_aabb(ray({-1, 1, std::nextafter(1.0, 2.0)}, {1, -1, 0}), kBox).hit);
}

TEST(IntersectRayAabb, NegativeDirectionsAndMisses) {
  expect_hit(intersect_ray_aabb(ray({2, 0.5, 0.5}, {-1, 0, 0}), kBox), 1, 2);
  EXPECT_FALSE(intersect_ray_aabb(ray({2, 0.5, 0.5}, {1, 0, 0}), kBox).hit);  // pointing away
  EXPECT_FALSE(intersect_ray_aabb(ray({2, 2, 2}, {1, 0, 0}), kBox).hit);
}

TEST(IntersectRayAabb, ZeroDirectionIsAPointTest) {
  expect_hit(intersect_ray_aabb(ray({0.5, 0, 1}, {0, 0, 0}), kBox), 0, INFINITY);
  EXPECT_FALSE(intersect_ray_aabb(ray({0.5, 0, 1.5}, {0, 0, 0}), kBox).hit);
}

TEST(IntersectRayAabb, ParameterRanges) {
  EXPECT_FALSE(intersect_ray_aabb(ray({-1, 0.5, 0.5}, {1, 0, 0}, 2, 1), kBox).hit);  // tmin > tmax
  expect_hit(intersect_ray_aabb(ray({2, 0.5, 0.5}, {1, 0, 0}, -INFINITY, INFINITY), kBox), -2, -1);  // a line
}

TEST(IntersectRayAabb, OutOfContractInputsGiveNoHit) {
  EXPECT_FALSE(intersect_ray_aabb(ray({kNan, 0.5, 0.5}, {1, 0, 0}), kBox).hit);
  EXPECT_FALSE(intersect_ray_aabb(ray({-1, 0.5, 0.5}, {1, kNan, 0}), kBox).hit);
  EXPECT_FALSE(intersect_ray_aabb(ray({-1, 0.5, 0.5}, {1, 0, 0}, kNan, 5), kBox).hit);
  EXPECT_FALSE(intersect_ray_aabb(ray({-INFINITY, 0.5, 0.5}, {1, 0, 0}), kBox).hit);
  EXPECT_FALSE(intersect_ray_aabb(ray({-1, 0.5, 0.5}, {1, 0, 0}, INFINITY, INFINITY), kBox).hit);
  EXPECT_FALSE(intersect_ray_aabb(ray({-1, 0.5, 0.5}, {1, 0, 0}), {{0, 0, 0}, {1, -1, 1}}).hit);  // inverted
  EXPECT_FALSE(intersect_ray_aabb(ray({-1, 0.5, 0.5}, {1, 0, 0}), {{0, 0, 0}, {INFINITY, 1, 1}}).hit);
}

}  // namespace
}  // namespace cc
