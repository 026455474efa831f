// distance_triangle_obb on configurations whose answers are known exactly: apart vertex to face,
// edge to edge and corner to face, a triangle parallel to a face (closest pairs not unique),
// touching, overlapping through a face, a corner through the triangle and crossing edges,
// degenerate triangles, a tiny triangle far from the origin, scales, and outside the domain.
// tests/collide_exact/triangle_box_distance_test.cpp checks the bounds in rationals.
#include "collide/triangle_box_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "rotations.h"

namespace cc {
namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();

Obb cube(const Vec3& center, double half = 1, const Mat3& axes = Mat3::identity()) {
  return {center, {half, half, half}, axes};
}

Triangle tri(const Vec3& a, const Vec3& b, const Vec3& c) { return {{a, b, c}}; }

void expect_vec(const Vec3& got, const Vec3& want, double within) {
  EXPECT_NEAR(got.x, want.x, within);
  EXPECT_NEAR(got.y, want.y, within);
  EXPECT_NEAR(got.z, want.z, within);
}

TEST(DistanceTriangleObb, ApartVertexToFace) {
  const Triangle t = tri({0.25, 0.5, 1.75}, {3, 3, 5}, {-2, 2, 6});  // its lowest vertex 0.75 above the top
  const Separation s = distance_triangle_obb(t, cube({0, 0, 0}));
  EXPECT_NEAR(s.distance, 0.75, s.distance_error);
  EXPECT_LE(s.distance_error, 1e-12);
  expect_vec(s.on_a, {0.25, 0.5, 1.75}, 1e-14);
  expect_vec(s.on_b, {0.25, 0.5, 1}, 1e-14);
}

TEST(DistanceTriangleObb, ApartCornerToTheTrianglesFace) {
  // The triangle in the plane x + y + z = 3 + sqrt 3 d, over the corner (1, 1, 1): d apart.
  const double d = 0.5, level = 3 + std::sqrt(3.0) * d;
  const Triangle t = tri({level, -4, 4}, {-4, level, 4}, {4, 4, level - 8});
  const Separation s = distance_triangle_obb(t, cube({0, 0, 0}));
  EXPECT_NEAR(s.distance, d, s.distance_error);
  EXPECT_LE(s.distance_error, 1e-12);
  expect_vec(s.on_b, {1, 1, 1}, 1e-14);
  const double along = d / std::sqrt(3.0);
  expect_vec(s.on_a, {1 + along, 1 + along, 1 + along}, 1e-12);
}

TEST(DistanceTriangleObb, ApartEdgeToFace) {
  // The triangle's edge from (-3, 1.5, 1.25) to (3, 1.5, 0.25) runs along the face y = 1 half a
  // unit off it; its third vertex is farther.
  const Triangle t = tri({-3, 1.5, 1.25}, {3, 1.5, 0.25}, {0, 5, 0.5});
  const Separation s = distance_triangle_obb(t, cube({0, 0, 0}));
  EXPECT_NEAR(s.distance, 0.5, s.distance_error);
  EXPECT_NEAR(s.on_b.y, 1, 1e-14);
  EXPECT_NEAR(s.on_a.y, 1.5, 1e-14);
}

TEST(DistanceTriangleObb, ApartEdgeToEdge) {
  // The triangle's edge along (1, -1, 0) through (1.5, 1.5, 0) crosses the box's edge x = y = 1
  // (along z) sqrt(1/2) away; its third vertex (5, 5, 0) is farther.
  const Triangle t = tri({-0.5, 3.5, 0}, {3.5, -0.5, 0}, {5, 5, 0});
  const Separation s = distance_triangle_obb(t, cube({0, 0, 0}));
  EXPECT_NEAR(s.distance, std::sqrt(0.5), s.distance_error);
  EXPECT_LE(s.distance_error, 1e-12);
  expect_vec(s.on_a, {1.5, 1.5, 0}, 1e-14);
  expect_vec(s.on_b, {1, 1, 0}, 1e-14);
}

TEST(DistanceTriangleObb, ParallelToAFaceAnyClosestPair) {
  const Triangle t = tri({-0.5, -0.5, 1.25}, {0.5, -0.5, 1.25}, {0, 0.5, 1.25});
  const Separation s = distance_triangle_obb(t, cube({0, 0, 0}));
  EXPECT_NEAR(s.distance, 0.25, s.distance_error);
  EXPECT_NEAR(s.on_a.z, 1.25, 1e-15);
  EXPECT_NEAR(s.on_b.z, 1, 1e-15);
  EXPECT_NEAR(s.on_a.x, s.on_b.x, 1e-14);  // straight down, wherever over the triangle
  EXPECT_NEAR(s.on_a.y, s.on_b.y, 1e-14);
}

TEST(DistanceTriangleObb, TouchingIsZero) {
  for (const double z : {1.0, -1.0}) {
    const Triangle t = tri({0, 0, z}, {3, 0, 3 * z}, {0, 3, 3 * z});
    const Separation s = distance_triangle_obb(t, cube({0, 0, 0}));
    EXPECT_NEAR(s.distance, 0, s.distance_error);
    EXPECT_LE(s.distance_error, 1e-12);
  }
}

TEST(DistanceTriangleObb, OverlappingThroughTheTopFace) {
  // A large horizontal triangle cutting the cube 0.25 below its top: pushing the box down by 1.25
  // or up by 0.75 separates them; up is shorter.
  const Triangle t = tri({-5, -5, 0.25}, {5, -5, 0.25}, {0, 5, 0.25});
  const Separation s = distance_triangle_obb(t, cube({0, 0, 0}));
  EXPECT_NEAR(s.distance, -0.75, s.distance_error);
  EXPECT_LE(s.distance_error, 1e-12);
  EXPECT_NEAR(s.on_a.z - s.on_b.z, -0.75, 1e-12);  // the box goes down by 0.75, and so does on_a - on_b
  EXPECT_NEAR(s.on_b.z, 1, 1e-12);                 // the box's top face
  EXPECT_NEAR(s.on_a.z, 0.25, 1e-12);
}

// A small flat triangle sunk 0.1 under a cube's top face near each of its corners: whichever of
// the face's two triangles it lies under, the witnesses are a meeting pair, 0.1 apart.
TEST(DistanceTriangleObb, ADepthsWitnessesMeetWhereverOnTheFace) {
  for (const double x : {-0.7, 0.7}) {
    for (const double y : {-0.7, 0.7}) {
      const Triangle t = tri({x - 0.2, y - 0.2, 0.9}, {x + 0.2, y - 0.2, 0.9}, {x, y + 0.2, 0.9});
      const Separation s = distance_triangle_obb(t, cube({0, 0, 0}));
      EXPECT_NEAR(s.distance, -0.1, 1e-12) << x << " " << y;
      EXPECT_NEAR(length(s.on_b - s.on_a), 0.1, 1e-12) << x << " " << y;
      EXPECT_LT(s.point_error, 1e-12) << x << " " << y;
    }
  }
}

TEST(DistanceTriangleObb, OverlappingThroughAFaceFromOutside) {
  // A vertex 0.125 inside the top face, the triangle rising away from it: 0.125 deep.
  const Triangle t = tri({0.25, 0.25, 0.875}, {4, 1, 6}, {1, 4, 6});
  const Separation s = distance_triangle_obb(t, cube({0, 0, 0}));
  EXPECT_NEAR(s.distance, -0.125, s.distance_error);
  EXPECT_LE(s.distance_error, 1e-12);
  expect_vec(s.on_a, {0.25, 0.25, 0.875}, 1e-12);
  expect_vec(s.on_b, {0.25, 0.25, 1}, 1e-12);
}

TEST(DistanceTriangleObb, ACornerThroughTheTriangle) {
  // The triangle in x + y + z = 3 - sqrt 3 d: the corner (1, 1, 1) pokes d through it; every
  // other separating axis is deeper.
  const double d = 0.25, level = 3 - std::sqrt(3.0) * d;
  const Triangle t = tri({level + 4, -2, -2}, {-2, level + 4, -2}, {-2, -2, level + 4});
  const Separation s = distance_triangle_obb(t, cube({0, 0, 0}));
  EXPECT_NEAR(s.distance, -d, s.distance_error);
  EXPECT_LE(s.distance_error, 1e-12);
  expect_vec(s.on_b, {1, 1, 1}, 1e-12);
}

TEST(DistanceTriangleObb, DegenerateTriangles) {
  // A segment (collinear vertices) passing 0.5 over the top face, and a point 2 to its side.
  const Triangle segment = tri({-3, 0, 1.5}, {3, 0, 1.5}, {0, 0, 1.5});
  EXPECT_NEAR(distance_triangle_obb(segment, cube({0, 0, 0})).distance, 0.5, 1e-12);
  const Triangle point = tri({3, 0, 0}, {3, 0, 0}, {3, 0, 0});
  const Separation s = distance_triangle_obb(point, cube({0, 0, 0}));
  EXPECT_NEAR(s.distance, 2, 1e-12);
  expect_vec(s.on_b, {1, 0, 0}, 1e-14);
  // A segment through the cube along x at height 0.5: pushing the box down 1.5 (or along y by 1,
  // or up by 0.5) separates them: 0.5 deep.
  const Triangle rod = tri({-3, 0, 0.5}, {3, 0, 0.5}, {3, 0, 0.5});
  EXPECT_NEAR(distance_triangle_obb(rod, cube({0, 0, 0})).distance, -0.5, 1e-12);
}

TEST(DistanceTriangleObb, AnEdgeNearlyParallelToABoxEdgePressedIntoAFace) {
  // The triangle's lowest edge lies 2^-35 inside the top face, turned 2^-30 from the box's x axis,
  // both placed by one rotation (so that the edge and the axis round): the edge pair's axis is
  // measured by the accurate cross product, so the bound stays at the rounding's scale (far below
  // the 2^-29 its sliver would cost).
  const double depth = 0x1p-35, turn = 0x1p-30;
  const Mat3 place = test::rotation(0.4, -1.3, 2.2);
  const Triangle t = tri(place * Vec3{-3, 0.1, 1 - depth}, place * Vec3{3, 0.1 + 6 * turn, 1 - depth}, place * Vec3{0, 0.3, 5});
  const Separation s = distance_triangle_obb(t, cube({0, 0, 0}, 1, place));
  EXPECT_NEAR(s.distance, -depth, s.distance_error + 0x1p-50);
  EXPECT_LE(s.distance_error, 0x1p-40);
}

TEST(DistanceTriangleObb, ScalesAndSwapsOfTheVertices) {
  const Triangle t = tri({0.25, 0.5, 1.75}, {3, 3, 5}, {-2, 2, 6});
  const Separation s = distance_triangle_obb(t, cube({0, 0, 0}));
  for (const int e : {-300, -40, 40, 300}) {
    const double k = std::ldexp(1.0, e);
    const Triangle tk{{k * t.v[0], k * t.v[1], k * t.v[2]}};
    const Separation sk = distance_triangle_obb(tk, cube({0, 0, 0}, k));
    EXPECT_EQ(sk.distance, k * s.distance) << e;
  }
  const Triangle rolled{{t.v[1], t.v[2], t.v[0]}};
  EXPECT_NEAR(distance_triangle_obb(rolled, cube({0, 0, 0})).distance, s.distance, 1e-14);
}

TEST(DistanceTriangleObb, OutsideTheDomainIsNan) {
  const Triangle t = tri({0, 0, 5}, {1, 0, 5}, {0, 1, 5});
  EXPECT_TRUE(std::isnan(distance_triangle_obb(tri({kNan, 0, 0}, {1, 0, 0}, {0, 1, 0}), cube({0, 0, 0})).distance));
  EXPECT_TRUE(std::isnan(distance_triangle_obb(t, cube({0, kNan, 0})).distance));
  const Obb inverted{{0, 0, 0}, {1, -1, 1}, Mat3::identity()};
  const Separation s = distance_triangle_obb(t, inverted);
  EXPECT_TRUE(std::isnan(s.distance));
  EXPECT_TRUE(std::isinf(s.distance_error));
}

}  // namespace
}  // namespace cc
