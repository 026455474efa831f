#include "harness/judging/hull_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace cc::harness {
namespace {

TEST(HullDistance, FromAPointToAPolygonASegmentAndAPoint) {
  const std::vector<Vec3> square = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  EXPECT_EQ(distance_to_hull({1, 1, 3}, square), 3);     // above the inside: the plane
  EXPECT_EQ(distance_to_hull({1, 1, 0}, square), 0);     // inside, though no triangle's vertex
  EXPECT_EQ(distance_to_hull({5, 1, 0}, square), 3);     // beside an edge
  EXPECT_EQ(distance_to_hull({3, 3, 0}, square), std::sqrt(2.0));
  const std::vector<Vec3> segment = {{0, 0, 0}, {4, 0, 0}};
  EXPECT_EQ(distance_to_hull({2, 3, 4}, segment), 5);
  EXPECT_EQ(distance_to_hull({7, 4, 0}, segment), 5);
  EXPECT_EQ(distance_to_hull({1, 1, 1}, std::vector<Vec3>{{1, 1, 1}}), 0);
}

TEST(HullDistance, IsHausdorffBothWays) {
  const std::vector<Vec3> triangle = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, edge = {{0, 0, 0}, {4, 0, 0}};
  EXPECT_EQ(hull_distance(edge, triangle), 4);  // the triangle's far corner from the edge
  EXPECT_EQ(hull_distance(triangle, edge), 4);
  EXPECT_EQ(hull_distance(triangle, triangle), 0);
  EXPECT_EQ(hull_distance({}, triangle), std::numeric_limits<double>::infinity());
  EXPECT_EQ(hull_distance({}, {}), 0);
}

TEST(HullDistance, SubnormalAndHugeSetsAreMeasuredScaled) {
  for (int e : {-1070, -1000, 0, 500, 1000}) {
    const double s = std::ldexp(1.0, e);
    const std::vector<Vec3> a = {{0, 0, 0}, {4 * s, 0, 0}}, b = {{0, 3 * s, 0}, {4 * s, 3 * s, 0}};
    EXPECT_EQ(hull_distance(a, b), 3 * s) << e;
  }
}

}  // namespace
}  // namespace cc::harness
