// distance_triangle_triangle on configurations whose answers are known exactly: parallel faces,
// a vertex over a face, crossing edges, one triangle piercing the other, coplanar and apart,
// degenerate triangles, an edge pair not closest with one triangle behind it, large faces nearly
// touching, and outside the domain. tests/collide_exact/triangle_distance_test.cpp
// checks the bounds in rationals.
#include "collide/triangle_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cc {
namespace {

const Triangle kFloor{{Vec3{0, 0, 0}, Vec3{4, 0, 0}, Vec3{0, 4, 0}}};

Triangle lifted(const Triangle& t, const Vec3& by) { return {{t.v[0] + by, t.v[1] + by, t.v[2] + by}}; }

TEST(DistanceTriangleTriangle, ParallelFacesAreApartByTheirPlanesDistance) {
  const Separation s = distance_triangle_triangle(kFloor, lifted(kFloor, {1, 1, 3}));
  EXPECT_EQ(s.distance, 3);
  EXPECT_EQ(s.on_b.z - s.on_a.z, 3);
  EXPECT_LE(s.distance_error, 0x1p-44);
}

TEST(DistanceTriangleTriangle, AVertexOverAFace) {
  const Triangle roof{{Vec3{1, 1, 2}, Vec3{1, 1, 9}, Vec3{3, 3, 9}}};
  const Separation s = distance_triangle_triangle(kFloor, roof);
  EXPECT_EQ(s.distance, 2);
  EXPECT_EQ(s.on_a, (Vec3{1, 1, 0}));
  EXPECT_EQ(s.on_b, (Vec3{1, 1, 2}));
}

TEST(DistanceTriangleTriangle, CrossingEdgesAndAPiercingTriangleAreAtZero) {
  // An edge of b crosses the floor's interior: the triangles meet where no vertex or edge pair does.
  const Triangle pierce{{Vec3{1, 1, -1}, Vec3{1, 1, 1}, Vec3{9, 9, 5}}};
  const Separation s = distance_triangle_triangle(kFloor, pierce);
  EXPECT_LE(s.distance, s.distance_error);
  EXPECT_LE(s.distance_error, 0x1p-40);  // a few hundred ULPs of the coordinates (up to 9)
  const Triangle over_edge{{Vec3{2, -1, 0}, Vec3{2, 1, 0}, Vec3{2, 0, 5}}};  // crossing the floor's edge y = 0
  EXPECT_EQ(distance_triangle_triangle(kFloor, over_edge).distance, 0);
}

TEST(DistanceTriangleTriangle, CoplanarAndApart) {
  const Triangle beside{{Vec3{5, 0, 0}, Vec3{9, 0, 0}, Vec3{5, 4, 0}}};
  EXPECT_EQ(distance_triangle_triangle(kFloor, beside).distance, 1);
}

TEST(DistanceTriangleTriangle, DegenerateTrianglesAreSegmentsAndPoints) {
  const Triangle segment{{Vec3{1, 1, 5}, Vec3{3, 3, 5}, Vec3{2, 2, 5}}};
  EXPECT_EQ(distance_triangle_triangle(kFloor, segment).distance, 5);
  const Triangle point{{Vec3{6, 4, 0}, Vec3{6, 4, 0}, Vec3{6, 4, 0}}};
  const Separation s = distance_triangle_triangle(kFloor, point);  // nearest the hypotenuse x + y = 4
  EXPECT_NEAR(s.distance, 6 / std::sqrt(2.0), s.distance_error);
}

TEST(DistanceTriangleTriangle, AnEdgePairIsTakenAsClosestOnlyWithBothTrianglesBehindItsWitnesses) {
  // The first edge pair tried has a's third vertex behind its witness but not b's: not closest.
  const Triangle a{{Vec3{2, -4, 3}, Vec3{3, 3, 6}, Vec3{-2, -2, -5}}};
  const Triangle b{{Vec3{0, 6, 5}, Vec3{3, -2, 0}, Vec3{3, 0, 3}}};
  const Separation s = distance_triangle_triangle(a, b);
  EXPECT_NEAR(s.distance, 0.071662547294497753, 1e-15);
  EXPECT_LE(s.distance_error, 1e-12);
}

TEST(DistanceTriangleTriangle, NearlyTouchingFacesFarLargerThanTheirGapKeepATightBound) {
  // b is a slid in its plane and lifted by 1e-9: the witnesses' rounding (about 1e-13) turns their
  // direction by 1e-4, the face's normal does not turn.
  const Triangle a{{Vec3{1000.1, 200.3, -300.7}, Vec3{-800.9, 900.1, 100.3}, Vec3{300.3, -700.7, 800.9}}};
  const Vec3 n = cross(a.v[1] - a.v[0], a.v[2] - a.v[0]);
  const Vec3 by = (1e-9 / std::sqrt(dot(n, n))) * n + 0.25 * (a.v[1] - a.v[0]);
  const Separation s = distance_triangle_triangle(a, {{a.v[0] + by, a.v[1] + by, a.v[2] + by}});
  EXPECT_NEAR(s.distance, 1e-9, 1e-11);
  EXPECT_LE(s.distance_error, 1e-10);  // the distance alone were the normal not tried
}

TEST(DistanceTriangleTriangle, OutsideTheDomainIsNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Separation s = distance_triangle_triangle(kFloor, {{Vec3{nan, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}});
  EXPECT_TRUE(std::isnan(s.distance));
}

}  // namespace
}  // namespace cc
