// distance_segment_segment on configurations whose answers are known exactly: skew, crossing,
// parallel (closest pairs not unique), collinear, end to interior, point segments, and outside
// the domain. tests/collide_exact/segment_distance_test.cpp checks the bounds in rationals.
#include "collide/segment_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cc {
namespace {

TEST(DistanceSegmentSegment, SkewSegmentsMeetAtTheirCommonPerpendicular) {
  const Separation s = distance_segment_segment({{-1, 0, 0}, {1, 0, 0}}, {{0.5, -1, 2}, {0.5, 1, 2}});
  EXPECT_EQ(s.distance, 2);
  EXPECT_EQ(s.on_a, (Vec3{0.5, 0, 0}));
  EXPECT_EQ(s.on_b, (Vec3{0.5, 0, 2}));
  EXPECT_LE(s.distance_error, 0x1p-44);  // a few dozen ULPs of the coordinates
}

TEST(DistanceSegmentSegment, CrossingSegmentsAreAtZero) {
  const Separation s = distance_segment_segment({{-1, -1, 0}, {1, 1, 0}}, {{-1, 1, 0}, {1, -1, 0}});
  EXPECT_EQ(s.distance, 0);
  EXPECT_LE(s.distance_error, 0x1p-48);
}

TEST(DistanceSegmentSegment, ParallelSegmentsGiveSomeClosestPair) {
  const Separation s = distance_segment_segment({{0, 0, 0}, {4, 0, 0}}, {{1, 3, 0}, {6, 3, 0}});
  EXPECT_NEAR(s.distance, 3, s.distance_error);
  EXPECT_LE(s.distance_error, 0x1p-42);
  EXPECT_EQ(s.on_b.y - s.on_a.y, 3);
  EXPECT_GE(s.on_a.x, 1);  // within the overlap of the two ranges
  EXPECT_LE(s.on_a.x, 4);
}

TEST(DistanceSegmentSegment, CollinearApartAndEndToInterior) {
  EXPECT_EQ(distance_segment_segment({{0, 0, 0}, {1, 0, 0}}, {{3, 0, 0}, {5, 0, 0}}).distance, 2);
  const Separation t = distance_segment_segment({{0, 0, 0}, {0, 0, 4}}, {{3, 4, 2}, {3, 4, 9}});
  EXPECT_EQ(t.distance, 5);  // a's interior against b's first end (3-4-5)
  EXPECT_EQ(t.on_b, (Vec3{3, 4, 2}));
}

TEST(DistanceSegmentSegment, PointSegments) {
  EXPECT_EQ(distance_segment_segment({{1, 1, 1}, {1, 1, 1}}, {{1, 4, 5}, {1, 4, 5}}).distance, 5);
  const Separation s = distance_segment_segment({{0, 3, 0}, {0, 3, 0}}, {{-2, 0, 0}, {2, 0, 0}});
  EXPECT_EQ(s.distance, 3);
  EXPECT_EQ(s.on_b, (Vec3{0, 0, 0}));
}

TEST(DistanceSegmentSegment, OutsideTheDomainIsNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Separation s = distance_segment_segment({{nan, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, 1, 0}});
  EXPECT_TRUE(std::isnan(s.distance));
  EXPECT_TRUE(std::isinf(s.distance_error));
}

}  // namespace
}  // namespace cc
