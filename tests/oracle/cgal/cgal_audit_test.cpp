// CGAL's party on cases worked out by hand: touching (a hit), one ulp apart (a miss), parallel
// and degenerate shapes, and the line in a face's plane that CGAL 5.5's Line_3 test gets wrong;
// signed distances of balls, a ball's centre in each tetrahedron of a box (CGAL 5.5 measures a
// point's distance to a tetrahedron rightly only when it is positively oriented);
// k-DOP slabs one by one; the first point of a ray on a mesh, exact to the double around it; the
// faces of two placed meshes that meet and their distance.
#include "oracle/cgal/cgal_audit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "harness/kinds/ray_mesh.h"
#include "harness/model/mesh_query.h"

namespace cc::cgal {
namespace {

constexpr double kInf = INFINITY;
const double kAboveOne = std::nextafter(1.0, 2.0);

Aabb unit_box() { return {{0, 0, 0}, {1, 1, 1}}; }
Triangle triangle(Vec3 a, Vec3 b, Vec3 c) { return {{a, b, c}}; }
Obb obb(Vec3 center, Vec3 half, Mat3 axes = Mat3::identity()) { return {center, half, axes}; }
// A quarter turn about z: exact in doubles.
const Mat3 kQuarterTurn = Mat3::from_columns({0, 1, 0}, {-1, 0, 0}, {0, 0, 1});

TEST(CgalSpheres, TouchingIsAHitAtSignZero) {
  const CgalAnswer a = cgal_answer(Sphere{{0, 0, 0}, 1}, Sphere{{3, 0, 0}, 2});
  EXPECT_TRUE(a.hit);
  EXPECT_EQ(a.margin_sign, 0);
}

TEST(CgalSpheres, OneUlpApartIsAMissAndOverlapIsPositive) {
  const CgalAnswer apart = cgal_answer(Sphere{{0, 0, 0}, 1}, Sphere{{std::nextafter(3.0, 4.0), 0, 0}, 2});
  EXPECT_FALSE(apart.hit);
  EXPECT_EQ(apart.margin_sign, -1);
  EXPECT_EQ(cgal_answer(Sphere{{0, 0, 0}, 1}, Sphere{{0, 2, 0}, 2}).margin_sign, 1);
}

TEST(CgalSpheres, SubnormalRadiiOverlapExactly) {
  // Same centre, radii 5e-324: (r_a + r_b)^2 > 0 = |c_a - c_b|^2, however small.
  const CgalAnswer a = cgal_answer(Sphere{{0, 7.5, 8}, 5e-324}, Sphere{{0, 7.5, 8}, 5e-324});
  EXPECT_EQ(a.margin_sign, 1);
  EXPECT_EQ(cgal_answer(Sphere{{1, 1, 1}, 0}, Sphere{{1, 1, 1}, 0}).margin_sign, 0);  // two points, equal
}

TEST(CgalSpheres, TheSignedDistanceIsRoundedDown) {
  EXPECT_EQ(cgal_answer(Sphere{{0, 0, 0}, 1}, Sphere{{3, 4, 0}, 2}).distance_down, 2);
  EXPECT_EQ(cgal_answer(Sphere{{0, 0, 0}, 1}, Sphere{{0.5, 0, 0}, 2}).distance_down, -2.5);
  // sqrt 2 - 1 rounded down, below the nearest double 0.41421356237309515.
  EXPECT_EQ(cgal_answer(Sphere{{0, 0, 0}, 0.5}, Sphere{{1, 1, 0}, 0.5}).distance_down, 0.41421356237309503);
}

TEST(CgalBallBox, OutsideInsideAndOnTheBoundary) {
  const Obb cube = obb({0, 0, 0}, {1, 1, 1});
  const CgalAnswer corner = cgal_answer(Sphere{{3, 3, 2}, 1}, cube);  // (2, 2, 1) beyond the corner: 3 - 1
  EXPECT_FALSE(corner.hit);
  EXPECT_EQ(corner.distance_down, 2);
  EXPECT_EQ(corner.margin_sign, -1);
  const CgalAnswer touching = cgal_answer(Sphere{{0, 0, 2}, 1}, cube);
  EXPECT_TRUE(touching.hit);
  EXPECT_EQ(touching.margin_sign, 0);
  EXPECT_EQ(cgal_answer(Sphere{{1, 1, 1}, 0}, cube).margin_sign, 0);  // a point on a corner
  // Centres inside: each of the cube's six tetrahedra holds one of these points, half of the
  // tetrahedra negatively oriented as Kuhn's construction gives them; the depth is the nearest
  // face's distance.
  for (const Vec3& c : {Vec3{0.5, 0.25, 0.125}, Vec3{0.25, 0.5, 0.125}, Vec3{0.5, 0.125, 0.25}, Vec3{0.125, 0.5, 0.25},
                        Vec3{0.25, 0.125, 0.5}, Vec3{0.125, 0.25, 0.5}}) {
    const CgalAnswer inside = cgal_answer(Sphere{c, 0.25}, cube);
    EXPECT_TRUE(inside.hit);
    EXPECT_EQ(inside.margin_sign, 1);
    EXPECT_EQ(inside.distance_down, -(0.5 + 0.25)) << c.x << ' ' << c.y << ' ' << c.z;
  }
  // A flat box is all boundary: a point in it is at depth 0.
  EXPECT_EQ(cgal_answer(Sphere{{0.5, 0.5, 0}, 0.25}, obb({0, 0, 0}, {1, 1, 0})).distance_down, -0.25);
}

TEST(CgalBoxes, SharedFaceIsAHitOneUlpApartAMiss) {
  EXPECT_TRUE(cgal_answer(unit_box(), Aabb{{1, 0, 0}, {2, 1, 1}}).hit);
  EXPECT_FALSE(cgal_answer(unit_box(), Aabb{{kAboveOne, 0, 0}, {2, 1, 1}}).hit);
  EXPECT_TRUE(cgal_answer(unit_box(), Aabb{{1, 1, 1}, {1, 1, 1}}).hit);  // a point box on the corner
}

TEST(CgalRays, LineInAFacePlaneMissesWhenItsSlabsDoNotOverlap) {
  // x = 2 throughout (the box's flat x slab); y in the box needs t in [131071.89.., 131072.14..],
  // z in it needs t in [-2, 0]: a miss (CGAL 5.5's Line_3 test says hit).
  const Ray line{{2, 1.75, 0}, {0, 16, 2}, -kInf, kInf};
  EXPECT_FALSE(cgal_answer(line, Aabb{{2, 2097152, -4}, {2, 2097156, 0}}).hit);
  const Ray through_corner{{2, 2097152, 0}, {0, 16, 2}, -kInf, kInf};  // at t = 0 on the box's edge
  EXPECT_TRUE(cgal_answer(through_corner, Aabb{{2, 2097152, -4}, {2, 2097156, 0}}).hit);
}

TEST(CgalRays, RaysAndSegmentsEndWhereTheirRangeDoes) {
  EXPECT_FALSE(cgal_answer(Ray{{0.5, 0.5, 2}, {0, 0, 1}, 0, kInf}, unit_box()).hit);  // pointing away
  EXPECT_TRUE(cgal_answer(Ray{{0.5, 0.5, 2}, {0, 0, -1}, 0, kInf}, unit_box()).hit);
  EXPECT_TRUE(cgal_answer(Ray{{0.5, 0.5, 2}, {0, 0, 1}, -kInf, 0}, unit_box()).hit);  // t <= 0: backwards
  // A segment from z = 3 down to z = 1 exactly touches the top face; one ulp of t short, it misses.
  EXPECT_TRUE(cgal_answer(Ray{{0.5, 0.5, 3}, {0, 0, -1}, 0, 2}, unit_box()).hit);
  EXPECT_FALSE(cgal_answer(Ray{{0.5, 0.5, 3}, {0, 0, -1}, 0, std::nextafter(2.0, 0.0)}, unit_box()).hit);
  EXPECT_FALSE(cgal_answer(Ray{{0.5, 0.5, 0.5}, {0, 0, 1}, 1, 0}, unit_box()).hit);  // tmin > tmax: no point
}

TEST(CgalRays, ZeroDirectionIsAPointAndASubnormalComponentIsParallel) {
  EXPECT_TRUE(cgal_answer(Ray{{1, 1, 1}, {0, 0, 0}, 0, kInf}, unit_box()).hit);
  EXPECT_FALSE(cgal_answer(Ray{{kAboveOne, 1, 1}, {0, 0, 0}, -kInf, kInf}, unit_box()).hit);
  // 1 / 5e-324 overflows: the contract makes the x component 0, so x stays on the face x = 1.
  EXPECT_TRUE(cgal_answer(Ray{{1, 0.5, -5}, {5e-324, 0, 1}, 0, kInf}, unit_box()).hit);
}

TEST(CgalTriangleBox, VertexOnTheCornerIsAHitOneUlpOffAMiss) {
  EXPECT_TRUE(cgal_answer(triangle({1, 1, 1}, {2, 1, 1}, {2, 2, 3}), unit_box()).hit);
  EXPECT_FALSE(cgal_answer(triangle({kAboveOne, 1, 1}, {2, 1, 1}, {2, 2, 3}), unit_box()).hit);
  // In the plane of the top face, overlapping it.
  EXPECT_TRUE(cgal_answer(triangle({0.5, 0.5, 1}, {5, 0.5, 1}, {0.5, 5, 1}), unit_box()).hit);
}

TEST(CgalTriangleBox, DegenerateTrianglesAreTheirSegmentOrPoint) {
  // Collinear, the middle vertex listed last: the segment from (-1,..) to (3,..) crosses the box.
  EXPECT_TRUE(cgal_answer(triangle({-1, 0.5, 0.5}, {3, 0.5, 0.5}, {2, 0.5, 0.5}), unit_box()).hit);
  EXPECT_FALSE(cgal_answer(triangle({2, 0.5, 0.5}, {3, 0.5, 0.5}, {2.5, 0.5, 0.5}), unit_box()).hit);
  EXPECT_TRUE(cgal_answer(triangle({1, 1, 1}, {1, 1, 1}, {1, 1, 1}), unit_box()).hit);
  EXPECT_FALSE(cgal_answer(triangle({1, 1, kAboveOne}, {1, 1, kAboveOne}, {1, 1, kAboveOne}), unit_box()).hit);
}

TEST(CgalTriangles, CoplanarSharingAnEdgeHitParallelPlanesMiss) {
  const Triangle a = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_TRUE(cgal_answer(a, triangle({1, 0, 0}, {0, 1, 0}, {1, 1, 0})).hit);
  EXPECT_FALSE(cgal_answer(a, triangle({0, 0, 1e-300}, {1, 0, 1e-300}, {0, 1, 1e-300})).hit);
  EXPECT_FALSE(cgal_answer(a, triangle({kAboveOne, 0, 0}, {2, 0, 0}, {2, 1, 0})).hit);  // beyond a's vertex
}

TEST(CgalTriangles, SegmentAndPointTriangles) {
  const Triangle a = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_TRUE(cgal_answer(a, triangle({0.25, 0.25, -1}, {0.25, 0.25, 1}, {0.25, 0.25, 0})).hit);  // pierces
  EXPECT_TRUE(cgal_answer(a, triangle({0.5, 0.5, 0}, {0.5, 0.5, 0}, {0.5, 0.5, 0})).hit);  // on the hypotenuse
  EXPECT_FALSE(cgal_answer(a, triangle({0.5, kAboveOne / 2, 0}, {0.5, kAboveOne / 2, 0}, {0.5, kAboveOne / 2, 0})).hit);
  const Triangle p = triangle({3, 3, 3}, {3, 3, 3}, {3, 3, 3});
  EXPECT_TRUE(cgal_answer(p, p).hit);
  EXPECT_TRUE(cgal_answer(triangle({0, 0, 5}, {2, 2, 5}, {1, 1, 5}), triangle({0, 2, 5}, {2, 0, 5}, {1, 1, 5})).hit);
}

TEST(CgalObbs, AParallelepipedIsSolid) {
  // A small triangle well inside a box rotated a quarter turn: no boundary meets it.
  const Obb box = obb({0, 0, 0}, {1, 2, 3}, kQuarterTurn);
  EXPECT_TRUE(cgal_answer(triangle({0.1, 0.1, 0}, {0.2, 0.1, 0}, {0.1, 0.2, 0}), box).hit);
  // The quarter turn spans x in [-2, 2], y in [-1, 1]: x = 2 touches, one ulp beyond misses.
  EXPECT_TRUE(cgal_answer(triangle({2, 0, 0}, {5, 0, 0}, {5, 1, 0}), box).hit);
  EXPECT_FALSE(cgal_answer(triangle({std::nextafter(2.0, 3.0), 0, 0}, {5, 0, 0}, {5, 1, 0}), box).hit);
  EXPECT_FALSE(cgal_answer(triangle({0, 1.5, 0}, {1, 1.5, 0}, {0, 1.5, 1}), box).hit);
}

TEST(CgalObbs, ZeroHalfExtentsSpanRectanglesSegmentsAndPoints) {
  const Obb cube = obb({0, 0, 0}, {1, 1, 1});
  EXPECT_TRUE(cgal_answer(cube, obb({1, 0, 0}, {0, 5, 5})).hit);                  // a rectangle on a face
  EXPECT_FALSE(cgal_answer(cube, obb({kAboveOne, 0, 0}, {0, 5, 5})).hit);
  EXPECT_TRUE(cgal_answer(cube, obb({0, 0, 1}, {0, 0, 0})).hit);                  // a point on a face
  EXPECT_TRUE(cgal_answer(obb({0, 0, 0}, {0, 0, 0}), cube).hit);                  // a point inside
  // The quarter turn's second axis is x: segments along x over [1, 5] (touching) and [1.5, 4.5].
  EXPECT_TRUE(cgal_answer(cube, obb({3, 0, 0}, {0, 2, 0}, kQuarterTurn)).hit);
  EXPECT_FALSE(cgal_answer(cube, obb({3, 0, 0}, {0, 1.5, 0}, kQuarterTurn)).hit);
  EXPECT_FALSE(cgal_answer(cube, obb({3, 0, 0}, {2, 0, 0}, kQuarterTurn)).hit);  // along y, at x = 3
}

// Two boxes' signed distance, rounded down: apart face to face and corner to corner, touching,
// overlapping through a face (the least depth), a segment through a square (depth 0.5 though
// neither has an inside), two squares crossing in one plane (0).
TEST(CgalObbs, TheSignedDistanceIsTheGapOrMinusTheDepth) {
  const Obb cube = obb({0, 0, 0}, {1, 1, 1});
  EXPECT_EQ(cgal_answer(cube, obb({3.5, 0.25, -0.5}, {1, 1, 1})).distance_down, 1.5);
  EXPECT_NEAR(*cgal_answer(cube, obb({3, 4, 14}, {1, 1, 1})).distance_down, std::sqrt(149.0), 1e-14);
  EXPECT_EQ(cgal_answer(cube, obb({2, 0.5, 0.5}, {1, 1, 1})).distance_down, 0);
  const CgalAnswer deep = cgal_answer(cube, obb({1.5, 0.2, 0}, {1, 1, 1}));
  EXPECT_TRUE(deep.hit);
  EXPECT_EQ(deep.distance_down, -0.5);
  EXPECT_EQ(cgal_answer(obb({0, 0, 0}, {1, 1, 0}), obb({0.5, 0, 0}, {0, 0, 1})).distance_down, -0.5);
  EXPECT_EQ(cgal_answer(obb({0, 0, 0}, {1, 1, 0}), obb({0.5, 0.5, 0}, {1, 1, 0})).distance_down, 0);
  EXPECT_EQ(cgal_answer(cube, obb({0.5, 0, 0}, {0.25, 0.25, 0.25})).distance_down, -0.75);  // nested
}

// The tetrahedron x, y, z >= 0, x + y + z <= 1: on the diagonal slabs of k = 18 it spans x + y,
// x + z, y + z in [0, 1] and x - y, x - z, y - z in [-1, 1].
const std::vector<Vec3> kTetrahedron = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

TEST(CgalKdops, TouchingOnOneSlabIsAHitAtSignZeroThere) {
  // B spans x in [0.5, 0.625], y in [0.5, 0.875], z in [0.25, 0.5]; its least x + y is 0.5 + 0.5 = 1,
  // the tetrahedron's greatest: overlap 0 on the slab (1, 1, 0) alone. The others: x 0.125,
  // y 0.375, z 0.25, x + z 0.25 (B in [0.75, 1.125]), y + z 0.25 (B in [0.75, 1.375]), x - y 0.25
  // (B in [-0.25, 0]), x - z 0.125 (B in [0.125, 0.25]), y - z 0.125 (B in [0.25, 0.375]).
  const std::vector<Vec3> b = {{0.5, 0.5, 0.25}, {0.625, 0.875, 0.5}};
  const CgalAnswer a = cgal_answer(18, kTetrahedron, b);
  EXPECT_TRUE(a.hit);
  EXPECT_EQ(a.margin_sign, 0);
  EXPECT_EQ(a.slab_signs, (std::vector<int>{1, 1, 1, 0, 1, 1, 1, 1, 1}));
  EXPECT_EQ(cgal_answer(18, b, kTetrahedron).slab_signs, a.slab_signs);  // either order
}

TEST(CgalKdops, OneUlpApartOnOneSlabIsAMiss) {
  // As above with B's first x one ulp above 0.5: its least x + y is 1 + 2^-53, exact in FT (no
  // double holds it), so the slab (1, 1, 0) is apart by 2^-53 and nothing else changes sign.
  const double above_half = std::nextafter(0.5, 1.0);
  const CgalAnswer a =
      cgal_answer(18, kTetrahedron, {{above_half, 0.5, 0.25}, {0.625, 0.875, 0.5}});
  EXPECT_FALSE(a.hit);
  EXPECT_EQ(a.margin_sign, -1);
  EXPECT_EQ(a.slab_signs, (std::vector<int>{1, 1, 1, -1, 1, 1, 1, 1, 1}));
}

TEST(CgalKdops, ADiagonalSlabSeparatesWhereTheAxesOverlap) {
  // B spans x in [0.5, 0.75], y in [0.625, 0.75], z in [0.25, 0.5]: within the tetrahedron's box
  // (the 6-DOP: a hit), but its least x + y + z is 1.375 > 1, so k = 14's slab (1, 1, 1) separates.
  // k = 14's others, against [-1, 1]: x - y + z in [0.125, 0.5], x + y - z in [0.875, 1] (overlap
  // 0.125), x - y - z in [-0.5, -0.375].
  const std::vector<Vec3> b = {{0.5, 0.625, 0.25}, {0.75, 0.75, 0.5}};
  const CgalAnswer box = cgal_answer(6, kTetrahedron, b);
  EXPECT_TRUE(box.hit);
  EXPECT_EQ(box.slab_signs, (std::vector<int>{1, 1, 1}));
  const CgalAnswer dop = cgal_answer(14, kTetrahedron, b);
  EXPECT_FALSE(dop.hit);
  EXPECT_EQ(dop.margin_sign, -1);
  EXPECT_EQ(dop.slab_signs, (std::vector<int>{1, 1, 1, -1, 1, 1, 1}));
}

TEST(CgalKdops, APointInsideOverlapsByZeroAndAnEmptySetByNothing) {
  // A single point's slab has no width: inside the other k-DOP every overlap is 0.
  const CgalAnswer point = cgal_answer(26, kTetrahedron, {{0.25, 0.25, 0.25}});
  EXPECT_TRUE(point.hit);
  EXPECT_EQ(point.slab_signs, std::vector<int>(13, 0));
  const CgalAnswer empty = cgal_answer(6, kTetrahedron, {});
  EXPECT_FALSE(empty.hit);
  EXPECT_EQ(empty.margin_sign, -1);
  EXPECT_EQ(empty.slab_signs, (std::vector<int>{-1, -1, -1}));
}

// Two parallel right triangles, face 0 in the plane z = 2 and face 1 in z = 1, each with the legs
// x, y in [0, 4] (hypotenuse x + y = 4), and face 2 far off; face 3 degenerate, the segment
// from (10, 0, 0) to (12, 0, 0) (its middle vertex listed last).
harness::RayMeshInput ray_on_mesh(Ray ray) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 2}, {4, 0, 2}, {0, 4, 2}, {0, 0, 1}, {4, 0, 1}, {0, 4, 1},
                   {20, 20, 0}, {21, 20, 0}, {20, 21, 0}, {10, 0, 0}, {12, 0, 0}, {11, 0, 0}};
  mesh.faces = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
  return {harness::triangles_mesh(mesh), ray, {}};
}

// CGAL's answer for the ray and the mesh of a case.
CgalAnswer answer(const harness::RayMeshInput& in) { return cgal_answer(in.ray, in.mesh, in.library); }

using Faces = std::vector<std::uint32_t>;

TEST(CgalRayMesh, TheFirstOfTwoFacesHitIsExactAndBothAreListed) {
  // Up from (1, 1, 0) at speed 3: z = 1 at t = 1/3, z = 2 at t = 2/3. 1/3 is no double: the
  // double 1.0 / 3 is the one below it (0.33333333333333331...), the next one above.
  const CgalAnswer a = answer(ray_on_mesh({{1, 1, 0}, {0, 0, 3}, 0, kInf}));
  EXPECT_TRUE(a.hit);
  EXPECT_EQ(a.faces, (Faces{0, 1}));
  ASSERT_TRUE(a.first_t);
  EXPECT_EQ(a.first_t->down, 1.0 / 3);
  EXPECT_EQ(a.first_t->up, std::nextafter(1.0 / 3, 1.0));
  // Downward from z = 5 at speed 1: z = 2 first, at t = 3, a double.
  const CgalAnswer down = answer(ray_on_mesh({{1, 1, 5}, {0, 0, -1}, 0, kInf}));
  EXPECT_EQ(down.faces, (Faces{0, 1}));
  ASSERT_TRUE(down.first_t);
  EXPECT_EQ(down.first_t->down, 3);
  EXPECT_EQ(down.first_t->up, 3);
}

TEST(CgalRayMesh, GrazingAnEdgeExactlyIsAHitOneUlpPastAMiss) {
  // From (3, 3, 3) along (-1, -1, -1): z = 2 at t = 1, at (2, 2, 2) on face 0's hypotenuse; z = 1
  // at t = 2, at (1, 1, 1) inside face 1.
  const CgalAnswer a = answer(ray_on_mesh({{3, 3, 3}, {-1, -1, -1}, 0, kInf}));
  EXPECT_EQ(a.faces, (Faces{0, 1}));
  ASSERT_TRUE(a.first_t);
  EXPECT_EQ(a.first_t->up, 1);
  // x one ulp (2^-51) larger: x + y = 4 + 2^-51 at z = 2, past the hypotenuse; face 1 is still hit.
  const CgalAnswer past = answer(ray_on_mesh({{std::nextafter(3.0, 4.0), 3, 3}, {-1, -1, -1}, 0, kInf}));
  EXPECT_EQ(past.faces, (Faces{1}));
  ASSERT_TRUE(past.first_t);
  EXPECT_EQ(past.first_t->down, 2);
  EXPECT_EQ(past.first_t->up, 2);
}

TEST(CgalRayMesh, ARayInTheFacesPlaneEntersAtItsEdge) {
  // Along x at speed 3 in the plane z = 1, at y = 1: face 1 spans x in [0, 3] there, so the
  // intersection is the segment t in [2/3, 5/3]; its first point is its entry, t = 2/3 (no double:
  // 2.0 / 3 is the one below).
  const auto first_t = [](double tmin, double tmax) { return answer(ray_on_mesh({{-2, 1, 1}, {3, 0, 0}, tmin, tmax})); };
  const CgalAnswer ray = first_t(0, kInf);
  EXPECT_EQ(ray.faces, (Faces{1}));
  ASSERT_TRUE(ray.first_t);
  EXPECT_EQ(ray.first_t->down, 2.0 / 3);
  EXPECT_EQ(ray.first_t->up, std::nextafter(2.0 / 3, 1.0));
  const CgalAnswer line = first_t(-kInf, kInf);  // the two rays from the origin
  ASSERT_TRUE(line.first_t);
  EXPECT_EQ(line.first_t->down, 2.0 / 3);
  const CgalAnswer backward = first_t(-kInf, 1);  // x <= 1: the segment t in [2/3, 1], from its far end
  ASSERT_TRUE(backward.first_t);
  EXPECT_EQ(backward.first_t->down, 2.0 / 3);
  const CgalAnswer inside = first_t(1, 4);  // starting inside the face: at tmin
  ASSERT_TRUE(inside.first_t);
  EXPECT_EQ(inside.first_t->down, 1);
  EXPECT_EQ(inside.first_t->up, 1);
  EXPECT_FALSE(first_t(-kInf, 0.5).hit);  // stops at x = -0.5
}

TEST(CgalRayMesh, AZeroDirectionIsTheOriginAloneAtTmin) {
  const CgalAnswer inside = answer(ray_on_mesh({{1, 1, 1}, {0, 0, 0}, 0.5, kInf}));
  EXPECT_EQ(inside.faces, (Faces{1}));
  ASSERT_TRUE(inside.first_t);
  EXPECT_EQ(inside.first_t->down, 0.5);
  EXPECT_EQ(inside.first_t->up, 0.5);
  const CgalAnswer on_edge = answer(ray_on_mesh({{2, 2, 2}, {0, 0, 0}, -kInf, kInf}));
  EXPECT_EQ(on_edge.faces, (Faces{0}));
  ASSERT_TRUE(on_edge.first_t);
  EXPECT_EQ(on_edge.first_t->up, -kInf);
  EXPECT_FALSE(answer(ray_on_mesh({{1, 1, 1.5}, {0, 0, 0}, 0, kInf})).hit);
  EXPECT_EQ(answer(ray_on_mesh({{11, 0, 0}, {0, 0, 0}, 0, kInf})).faces, (Faces{3}));  // on the segment face
}

TEST(CgalRayMesh, ASegmentEndingOnAFaceHitsIt) {
  const CgalAnswer a = answer(ray_on_mesh({{1, 1, 0}, {0, 0, 1}, 0, 1}));  // ends at (1, 1, 1)
  EXPECT_EQ(a.faces, (Faces{1}));
  ASSERT_TRUE(a.first_t);
  EXPECT_EQ(a.first_t->up, 1);
  EXPECT_FALSE(answer(ray_on_mesh({{1, 1, 0}, {0, 0, 1}, 0, std::nextafter(1.0, 0.0)})).hit);
  // Across the degenerate face 3 (a segment along x): at (11.5, 0, 0), t = 2 from (11.5, 0, -4).
  const CgalAnswer across = answer(ray_on_mesh({{11.5, 0, -4}, {0, 0, 2}, 0, kInf}));
  EXPECT_EQ(across.faces, (Faces{3}));
  ASSERT_TRUE(across.first_t);
  EXPECT_EQ(across.first_t->up, 2);
}

TEST(CgalRayMesh, ASubnormalDirectionComponentCounts) {
  // Down through (2, 2, z), on both hypotenuses, but drifting 5e-324 in x per unit of t: at z = 2
  // (t = 3) and z = 1 (t = 4) x + y exceeds 4. (ray_aabb's contract would make the drift 0.)
  EXPECT_TRUE(answer(ray_on_mesh({{2, 2, 5}, {0, 0, -1}, 0, kInf})).hit);
  EXPECT_FALSE(answer(ray_on_mesh({{2, 2, 5}, {5e-324, 0, -1}, 0, kInf})).hit);
}

TEST(CgalRayMesh, ATinyDirectionGivesAFirstTFarOut) {
  // Down from z = 5 at speed 2^-1000: z = 2 at t = 3 * 2^1000, a double (dir . dir = 2^-2000 is
  // none).
  const CgalAnswer far = answer(ray_on_mesh({{1, 1, 5}, {0, 0, -0x1p-1000}, 0, kInf}));
  ASSERT_TRUE(far.first_t);
  EXPECT_EQ(far.first_t->down, 0x3p1000);
  EXPECT_EQ(far.first_t->up, 0x3p1000);
  // At speed 2^-1074, t = 3 * 2^1074 is beyond the doubles.
  const CgalAnswer beyond = answer(ray_on_mesh({{1, 1, 5}, {0, 0, -0x1p-1074}, 0, kInf}));
  ASSERT_TRUE(beyond.first_t);
  EXPECT_EQ(beyond.first_t->down, std::numeric_limits<double>::max());
  EXPECT_EQ(beyond.first_t->up, kInf);
}

// The square [0, 2] x [0, 2] in the plane z = 0 as two triangles (face 0 below the diagonal,
// face 1 above it), and a degenerate face 2: the segment from (3, 0, 0) to (5, 0, 0).
harness::MeshRef square_and_segment() {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {3, 0, 0}, {5, 0, 0}, {4, 0, 0}};
  mesh.faces = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}};
  return harness::triangles_mesh(mesh);
}

// The square mesh as a, and as b placed by a rotation and a translation.
harness::MeshPair squares(const Mat3& rotation, const Vec3& translation) {
  return {square_and_segment(), square_and_segment(), {Mat3::identity(), {0, 0, 0}}, {rotation, translation}, {}};
}

using Pairs = std::vector<harness::FacePair>;

TEST(CgalMeshes, ParallelSquaresApartAreAsFarAsTheirPlanes) {
  const CgalAnswer a = cgal_answer(squares(Mat3::identity(), {0.25, 0.5, 0.75}));
  EXPECT_FALSE(a.hit);
  EXPECT_EQ(a.pairs, Pairs{});
  EXPECT_EQ(a.distance_down, 0.75);
  // One ulp above the plane: apart, and the distance rounds down to that ulp.
  const double ulp = 0x1p-1074;
  const CgalAnswer b = cgal_answer(squares(Mat3::identity(), {0.25, 0.5, ulp}));
  EXPECT_FALSE(b.hit);
  EXPECT_EQ(b.distance_down, ulp);
}

TEST(CgalMeshes, TouchingAndCrossingFacesAreListedAndAtZero) {
  // Moved up by 2: b's square [0, 2] x [2, 4] meets a's along the edge y = 2: a's face 1 holds
  // it whole and face 0 its end (2, 2); b's face 0 holds it whole and face 1 its end (0, 2). a's
  // face 0 (y <= x) and b's face 1 (y >= x + 2) do not meet, nor do the segments.
  const CgalAnswer shared_edge = cgal_answer(squares(Mat3::identity(), {0, 2, 0}));
  EXPECT_TRUE(shared_edge.hit);
  EXPECT_EQ(shared_edge.pairs, (Pairs{{0, 0}, {1, 0}, {1, 1}}));
  EXPECT_EQ(shared_edge.distance_down, 0);
  // Stood up across a's square (x -> x, y -> z, about (0, 1, -1)): b's square is x in [0, 2],
  // y = 1, z in [-1, 1], crossing a's plane along y = 1. a's face 0 holds x in [1, 2] of that
  // line, face 1 x in [0, 1]; b's face 0 (z <= x - 1) crosses it for x in [1, 2], face 1 for
  // x in [0, 1]: every pair meets, the two across at the point (1, 1, 0) alone.
  const Mat3 stand = Mat3::from_columns({1, 0, 0}, {0, 0, 1}, {0, -1, 0});
  const CgalAnswer crossing = cgal_answer(squares(stand, {0, 1, -1}));
  EXPECT_TRUE(crossing.hit);
  EXPECT_EQ(crossing.pairs, (Pairs{{0, 0}, {0, 1}, {1, 0}, {1, 1}}));
  EXPECT_EQ(crossing.distance_down, 0);
}

TEST(CgalMeshes, ADegenerateFaceMeetsAsItsSegment) {
  // Moved by -3 along x: b's segment lies on a's edge from (0, 0) to (2, 0), which face 0 holds
  // whole and face 1 at (0, 0); b's triangles lie at x <= -1.
  const CgalAnswer on_edge = cgal_answer(squares(Mat3::identity(), {-3, 0, 0}));
  EXPECT_TRUE(on_edge.hit);
  EXPECT_EQ(on_edge.pairs, (Pairs{{0, 2}, {1, 2}}));
  // Moved by -5 - 2^-50: the segment ends 2^-50 short of a's corner (0, 0).
  const CgalAnswer short_of = cgal_answer(squares(Mat3::identity(), {-5 - 0x1p-50, 0, 0}));
  EXPECT_FALSE(short_of.hit);
  EXPECT_EQ(short_of.pairs, Pairs{});
  EXPECT_EQ(short_of.distance_down, 0x1p-50);
}

TEST(CgalMeshes, TheDistanceOfTurnedMeshesIsExact) {
  // Turned by the 3-4-5 rotation about z and lifted by 3: b lies in the plane z = 3 over a's
  // square, 3 apart however its turned vertices round in doubles.
  const Mat3 turned = Mat3::from_columns({0.6, 0.8, 0}, {-0.8, 0.6, 0}, {0, 0, 1});
  const CgalAnswer over = cgal_answer(squares(turned, {0.1, 0.3, 3}));
  EXPECT_FALSE(over.hit);
  EXPECT_EQ(over.distance_down, 3);
  // Beside it: b's square [5, 7] x [6, 8] is nearest a's at the corners (2, 2) and (5, 6), 5
  // apart (a's segment's end (5, 0) is 6 from b).
  const CgalAnswer beside = cgal_answer(squares(Mat3::identity(), {5, 6, 0}));
  EXPECT_FALSE(beside.hit);
  EXPECT_EQ(beside.distance_down, 5);
}

TEST(CgalDiscWalls, TouchingASideOrAnEndIsAHitOneUlpApartAMiss) {
  const std::vector<Wall> walls{{{0, 0}, {4, 0}}, {{5, 0}, {5, 0}}, {{NAN, 0}, {2, 0.5}}};
  EXPECT_EQ(cgal_answer(Disc{{2, 0.5}, 0.5}, walls).faces, (std::vector<std::uint32_t>{0}));  // the side
  EXPECT_EQ(cgal_answer(Disc{{2, std::nextafter(0.5, 1.0)}, 0.5}, walls).faces, std::vector<std::uint32_t>{});
  // 3-4-5 from the end (4, 0): (4 + 3/16, 4/16) is 5/16 from it (and farther from the
  // pillar (5, 0)); midway between the end and the pillar, 0.5 from each.
  EXPECT_EQ(cgal_answer(Disc{{4.1875, 0.25}, 0.3125}, walls).faces, (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(cgal_answer(Disc{{4.1875, std::nextafter(0.25, 1.0)}, 0.3125}, walls).faces, std::vector<std::uint32_t>{});
  EXPECT_EQ(cgal_answer(Disc{{4.5, 0}, 0.5}, walls).faces, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(cgal_answer(Disc{{5, 0}, 0}, walls).faces, (std::vector<std::uint32_t>{1}));  // a point on the pillar
  EXPECT_FALSE(cgal_answer(Disc{{2, 0.5}, 0.5}, {{{NAN, 0}, {2, 0.5}}}).hit);             // a NaN end: never
}

TEST(CgalAnswer, InputsOutOfContractAreRefused) {
  EXPECT_THROW(answer(ray_on_mesh({{0, 0, 0}, {NAN, 0, 1}, 0, kInf})), std::invalid_argument);
  harness::RayMeshInput bad_face = ray_on_mesh({{1, 1, 0}, {0, 0, 1}, 0, kInf});
  Mesh mesh = *bad_face.mesh.mesh;
  mesh.faces.push_back({0, 1, 99});
  bad_face.mesh = harness::triangles_mesh(mesh);
  EXPECT_THROW(answer(bad_face), std::invalid_argument);
  EXPECT_THROW(cgal_answer(8, kTetrahedron, kTetrahedron), std::invalid_argument);
  EXPECT_THROW(cgal_answer(18, kTetrahedron, {{0, NAN, 0}}), std::invalid_argument);
  EXPECT_THROW(cgal_answer(Sphere{{NAN, 0, 0}, 1}, Sphere{{0, 0, 0}, 1}), std::invalid_argument);
  EXPECT_THROW(cgal_answer(Sphere{{0, 0, 0}, -1}, Sphere{{0, 0, 0}, 1}), std::invalid_argument);
  EXPECT_THROW(cgal_answer(Disc{{0, 0}, -1}, {{{0, 0}, {1, 0}}}), std::invalid_argument);
  EXPECT_THROW(cgal_answer(Disc{{INFINITY, 0}, 1}, {{{0, 0}, {1, 0}}}), std::invalid_argument);
  EXPECT_THROW(cgal_answer(Aabb{{1, 0, 0}, {0, 1, 1}}, unit_box()), std::invalid_argument);
  EXPECT_THROW(cgal_answer(Ray{{0, 0, 0}, {1, 0, 0}, kInf, kInf}, unit_box()), std::invalid_argument);
  harness::MeshPair nan_pose = squares(Mat3::identity(), {NAN, 0, 0});
  EXPECT_THROW(cgal_answer(nan_pose), std::invalid_argument);
  EXPECT_THROW(cgal_answer(obb({0, 0, 0}, {1, 1, 1}, Mat3::from_columns({1, 0, 0}, {1, 0, 0}, {0, 0, 1})),
                           obb({0, 0, 0}, {1, 1, 1})),
               std::invalid_argument);  // axes not independent
}

}  // namespace
}  // namespace cc::cgal
