#include "collide/triangle_intersection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "collide/triangle_triangle.h"
#include "test_random.h"

namespace cc {
namespace {

Triangle tri(Vec3 a, Vec3 b, Vec3 c) { return {{a, b, c}}; }

const Triangle kBase = tri({0, 0, 0}, {4, 0, 0}, {0, 4, 0});

std::vector<Vec3> corners(const TriangleIntersection& r) { return {r.points.begin(), r.points.begin() + r.count}; }

// The corners, sorted, for comparisons that do not depend on the order around a polygon.
std::vector<Vec3> sorted(std::vector<Vec3> p) {
  std::sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
  return p;
}

TEST(IntersectTriangles, CrossingTrianglesMeetAlongASegment) {
  // b stands across a's face: it meets a along x = 1, from y = 0 to y = 2 (where b's edges cross z = 0).
  const Triangle b = tri({1, -1, -1}, {1, 3, 1}, {1, -1, 1});
  EXPECT_EQ(sorted(corners(intersect_triangles(kBase, b))), (std::vector<Vec3>{{1, 0, 0}, {1, 1, 0}}));
  // Piercing a's interior: the two points where b's edges cross z = 0.
  const Triangle c = tri({1, 1, -1}, {1, 2, 1}, {2, 1, 1});
  EXPECT_EQ(sorted(corners(intersect_triangles(kBase, c))), (std::vector<Vec3>{{1, 1.5, 0}, {1.5, 1, 0}}));
}

TEST(IntersectTriangles, TouchingGivesTheTouchingVertexOrEdge) {
  EXPECT_EQ(corners(intersect_triangles(kBase, tri({0, 0, 0}, {-1, 0, 1}, {0, -1, 1}))), (std::vector<Vec3>{{0, 0, 0}}));
  EXPECT_EQ(corners(intersect_triangles(kBase, tri({2, 0, 0}, {2, -1, 1}, {3, -1, 1}))), (std::vector<Vec3>{{2, 0, 0}}));
  // b's edge lies in a's plane across a: the part of that edge inside a.
  EXPECT_EQ(sorted(corners(intersect_triangles(kBase, tri({1, -1, 0}, {1, 5, 0}, {1, 2, 3})))),
            (std::vector<Vec3>{{1, 0, 0}, {1, 3, 0}}));
  // Apart by one ulp of the plane: nothing, exactly.
  EXPECT_TRUE(intersect_triangles(kBase, tri({1, 1, 0x1p-1074}, {1, 2, 1}, {2, 1, 1})).empty());
  EXPECT_FALSE(intersect_triangles(kBase, tri({1, 1, 0}, {1, 2, 1}, {2, 1, 1})).empty());
}

TEST(IntersectTriangles, CoplanarTrianglesMeetInAPolygon) {
  // A star of David: the hexagon where two triangles of the same plane overlap.
  const Triangle up = tri({0, 0, 0}, {6, 0, 0}, {3, 6, 0}), down = tri({0, 4, 0}, {3, -2, 0}, {6, 4, 0});
  const TriangleIntersection r = intersect_triangles(up, down);
  ASSERT_EQ(r.count, 6);
  EXPECT_EQ(sorted(corners(r)), (std::vector<Vec3>{{1, 2, 0}, {2, 0, 0}, {2, 4, 0}, {4, 0, 0}, {4, 4, 0}, {5, 2, 0}}));
  // In order around the polygon: consecutive corners are its edges, never its diagonals.
  for (int i = 0; i < r.count; ++i) {
    const Vec3 d = r.points[(i + 1) % r.count] - r.points[i];
    EXPECT_LE(d.x * d.x + d.y * d.y, 5.0) << i;
  }
  // One inside the other: the inner one; sharing an edge only: that edge.
  EXPECT_EQ(sorted(corners(intersect_triangles(kBase, tri({1, 1, 0}, {2, 1, 0}, {1, 2, 0})))),
            (std::vector<Vec3>{{1, 1, 0}, {1, 2, 0}, {2, 1, 0}}));
  EXPECT_EQ(sorted(corners(intersect_triangles(kBase, tri({0, 0, 0}, {0, 4, 0}, {-3, 1, 0})))),
            (std::vector<Vec3>{{0, 0, 0}, {0, 4, 0}}));
  EXPECT_TRUE(intersect_triangles(kBase, tri({3, 3, 0}, {5, 3, 0}, {3, 5, 0})).empty());
}

TEST(IntersectTriangles, DegenerateTrianglesAreTheirPointSets) {
  const Triangle segment = tri({-1, 1, 0}, {5, 1, 0}, {2, 1, 0});  // in a's plane, across it
  EXPECT_EQ(sorted(corners(intersect_triangles(kBase, segment))), (std::vector<Vec3>{{0, 1, 0}, {3, 1, 0}}));
  const Triangle standing = tri({1, 1, -1}, {1, 1, 1}, {1, 1, 0.5});  // through a's face
  EXPECT_EQ(corners(intersect_triangles(standing, kBase)), (std::vector<Vec3>{{1, 1, 0}}));
  const Triangle point = tri({1, 1, 0}, {1, 1, 0}, {1, 1, 0});
  EXPECT_EQ(corners(intersect_triangles(kBase, point)), (std::vector<Vec3>{{1, 1, 0}}));
  EXPECT_EQ(corners(intersect_triangles(point, standing)), (std::vector<Vec3>{{1, 1, 0}}));
  // Two segments crossing in a plane, collinear and overlapping, skew.
  const Triangle s1 = tri({0, 0, 1}, {2, 2, 1}, {0, 0, 1}), s2 = tri({0, 2, 1}, {2, 0, 1}, {2, 0, 1});
  EXPECT_EQ(corners(intersect_triangles(s1, s2)), (std::vector<Vec3>{{1, 1, 1}}));
  const Triangle s3 = tri({1, 1, 1}, {3, 3, 1}, {3, 3, 1});
  EXPECT_EQ(sorted(corners(intersect_triangles(s1, s3))), (std::vector<Vec3>{{1, 1, 1}, {2, 2, 1}}));
  EXPECT_TRUE(intersect_triangles(s1, tri({0, 2, 2}, {2, 0, 1.5}, {2, 0, 1.5})).empty());
  EXPECT_TRUE(intersect_triangles(point, tri({1, 1, 1e-300}, {1, 1, 1e-300}, {1, 1, 1e-300})).empty());
}

TEST(IntersectTriangles, NonFiniteInputIsEmpty) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(intersect_triangles(kBase, tri({nan, 0, 0}, {1, 1, 1}, {1, 0, -1})).empty());
  EXPECT_TRUE(intersect_triangles(tri({0, 0, INFINITY}, {1, 1, 1}, {1, 0, -1}), kBase).empty());
}

TEST(IntersectTriangles, TinyAndHugeTrianglesAreScaledNotFlushed) {
  // Products of 2^-1000 coordinates underflow; the corners are computed on scaled copies.
  for (int e : {-1000, -500, 250, 300}) {
    const double s = std::ldexp(1.0, e);
    const Triangle a = tri({0, 0, 0}, {4 * s, 0, 0}, {0, 4 * s, 0}), b = tri({s, s, -s}, {s, 2 * s, s}, {2 * s, s, s});
    EXPECT_EQ(sorted(corners(intersect_triangles(a, b))), (std::vector<Vec3>{{s, 1.5 * s, 0}, {1.5 * s, s, 0}})) << e;
  }
}

// Exchanging the triangles gives the same points in the same order, bit for bit; something is
// reported exactly where the certified test says they meet, on grids of integers (where the
// test's band, 2^-44 of the scale, cannot reach across a gap).
TEST(IntersectTriangles, SymmetricAndConsistentWithTheTest) {
  test::Random random(7);
  int met = 0, polygons = 0;
  for (int i = 0; i < 20000; ++i) {
    Triangle a, b;
    for (Vec3& p : a.v) p = random.integer_point(3);
    for (Vec3& p : b.v) p = random.integer_point(3);
    if (i % 3 == 0) {  // coplanar, on the tilted plane x + y + z = 1
      for (Triangle* t : {&a, &b}) {
        for (Vec3& p : t->v) p.z = 1 - p.x - p.y;
      }
    }
    const bool on_grid = i % 5 != 0;
    if (!on_grid) {  // rounded crossings: b moved off the grid
      for (Vec3& p : b.v) p = p + random.in_cube(0.5);
    }
    const TriangleIntersection ab = intersect_triangles(a, b), ba = intersect_triangles(b, a);
    ASSERT_EQ(corners(ab), corners(ba)) << i;
    if (on_grid) {
      ASSERT_EQ(!ab.empty(), test_triangle_triangle(a, b)) << i;
    }
    met += !ab.empty();
    polygons += ab.count >= 3;
  }
  EXPECT_GT(met, 2000);
  EXPECT_GT(polygons, 1000);
}

}  // namespace
}  // namespace cc
