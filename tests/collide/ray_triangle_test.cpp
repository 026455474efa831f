#include "collide/ray_triangle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

namespace cc {
namespace {

const Triangle kTriangle{{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}};  // in z = 0
const double kNan = std::numeric_limits<double>::quiet_NaN();

Ray ray(Vec3 o, Vec3 d, double tmin = 0, double tmax = INFINITY) { return {o, d, tmin, tmax}; }

// A hit no later than the exact parameter and at most `slack` before it.
void expect_hit_at(const RayTriangleHit& h, double exact, double slack = 1e-13) {
  EXPECT_TRUE(h.hit);
  if (!h.hit) return;
  EXPECT_LE(h.t, exact);
  EXPECT_GE(h.t, exact - slack);
}

TEST(IntersectRayTriangle, ThroughTheMiddle) {
  expect_hit_at(intersect_ray_triangle(ray({0.25, 0.25, 1}, {0, 0, -1}), kTriangle), 1);
  expect_hit_at(intersect_ray_triangle(ray({0.25, 0.25, -2}, {0, 0, 1}), kTriangle), 2);  // from behind
  expect_hit_at(intersect_ray_triangle(ray({-1, -1, 1}, {1.25, 1.25, -1}), kTriangle), 1);  // slanted
  expect_hit_at(intersect_ray_triangle(ray({0.25, 0.25, 1}, {0, 0, -4}), kTriangle), 0.25);  // t in dir's units
}

TEST(IntersectRayTriangle, ThroughAnEdgeOrAVertex) {
  expect_hit_at(intersect_ray_triangle(ray({0.5, 0, 1}, {0, 0, -1}), kTriangle), 1);       // edge v0 v1
  expect_hit_at(intersect_ray_triangle(ray({0.5, 0.5, 1}, {0, 0, -1}), kTriangle), 1);     // edge v1 v2
  expect_hit_at(intersect_ray_triangle(ray({0, 0.25, 1}, {0, 0, -1}), kTriangle), 1);      // edge v2 v0
  expect_hit_at(intersect_ray_triangle(ray({1, 0, 1}, {0, 0, -1}), kTriangle), 1);         // vertex v1
  expect_hit_at(intersect_ray_triangle(ray({2, -1, 1}, {-1, 1, -1}), kTriangle), 1);       // slanted, at v1
  expect_hit_at(intersect_ray_triangle(ray({-1, -1, -1}, {1, 1, 1}), kTriangle), 1);       // at v0 from below
}

TEST(IntersectRayTriangle, JustOutsideAnEdgeOrAVertexMisses) {
  EXPECT_FALSE(intersect_ray_triangle(ray({0.5, -1e-9, 1}, {0, 0, -1}), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray({0.5 + 1e-9, 0.5, 1}, {0, 0, -1}), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray({1 + 1e-9, 0, 1}, {0, 0, -1}), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray({2, 2, 1}, {0, 0, -1}), kTriangle).hit);
}

TEST(IntersectRayTriangle, PointingAwayMissesUnlessTheRangeIsALine) {
  EXPECT_FALSE(intersect_ray_triangle(ray({0.25, 0.25, 1}, {0, 0, 1}), kTriangle).hit);
  expect_hit_at(intersect_ray_triangle(ray({0.25, 0.25, 1}, {0, 0, 1}, -INFINITY, INFINITY), kTriangle), -1);
  expect_hit_at(intersect_ray_triangle(ray({0.25, 0.25, 1}, {0, 0, 1}, -5, -0.5), kTriangle), -1);
  EXPECT_FALSE(intersect_ray_triangle(ray({0.25, 0.25, 1}, {0, 0, 1}, -0.5, 3), kTriangle).hit);
}

TEST(IntersectRayTriangle, GrazingInThePlane) {
  // Across the triangle: it enters through the edge x = 0 at t = 1.
  expect_hit_at(intersect_ray_triangle(ray({-1, 0.25, 0}, {1, 0, 0}), kTriangle), 1);
  // Starting inside: t = tmin.
  expect_hit_at(intersect_ray_triangle(ray({0.1, 0.1, 0}, {1, 0, 0}), kTriangle), 0);
  expect_hit_at(intersect_ray_triangle(ray({0.1, 0.1, 0}, {1, 0, 0}, 0.2, 5), kTriangle), 0.2);
  // Along an edge, and through a vertex only.
  expect_hit_at(intersect_ray_triangle(ray({-1, 0, 0}, {1, 0, 0}), kTriangle), 1);
  expect_hit_at(intersect_ray_triangle(ray({-1, 2, 0}, {1, -1, 0}), kTriangle), 1);  // along the hypotenuse
  expect_hit_at(intersect_ray_triangle(ray({1, -1, 0}, {0, 1, 0}), kTriangle), 1);   // touches v1 alone
  // In the plane but beside it, or pointing away.
  EXPECT_FALSE(intersect_ray_triangle(ray({-1, 2, 0}, {1, 0, 0}), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray({1 + 1e-9, -1, 0}, {0, 1, 0}), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray({-1, 0.25, 0}, {-1, 0, 0}), kTriangle).hit);
}

TEST(IntersectRayTriangle, ParallelAboveThePlaneMisses) {
  for (double z : {1.0, 1e-9, -1e-9}) {
    EXPECT_FALSE(intersect_ray_triangle(ray({-1, 0.25, z}, {1, 0, 0}), kTriangle).hit) << z;
    EXPECT_FALSE(intersect_ray_triangle(ray({-1, -1, z}, {1, 1, 0}), kTriangle).hit) << z;
  }
  // A tiny tilt towards the plane reaches it far away, beyond the triangle: still a miss.
  EXPECT_FALSE(intersect_ray_triangle(ray({-1, 0.25, 1e-9}, {1, 0, -1e-12}), kTriangle).hit);
  // Tilted enough to cross the plane over the triangle: a hit at z = 0.
  expect_hit_at(intersect_ray_triangle(ray({-1, 0.25, 1e-9}, {1, 0, -1e-9}), kTriangle), 1, 1e-3);
}

TEST(IntersectRayTriangle, SegmentsEndingBeforeOrAtTheTriangle) {
  const Vec3 o{0.25, 0.25, 1}, d{0, 0, -1};
  EXPECT_FALSE(intersect_ray_triangle(ray(o, d, 0, 0.5), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray(o, d, 0, 1 - 1e-9), kTriangle).hit);
  expect_hit_at(intersect_ray_triangle(ray(o, d, 0, 1), kTriangle), 1);  // ends on it
  expect_hit_at(intersect_ray_triangle(ray(o, d, 1, 2), kTriangle), 1);  // starts on it
  EXPECT_FALSE(intersect_ray_triangle(ray(o, d, 1 + 1e-9, 2), kTriangle).hit);
  // A degenerate range: the one point origin + t dir.
  expect_hit_at(intersect_ray_triangle(ray(o, d, 1, 1), kTriangle), 1);
  EXPECT_FALSE(intersect_ray_triangle(ray(o, d, 0.5, 0.5), kTriangle).hit);
}

TEST(IntersectRayTriangle, TheParameterIsNeverLaterThanTheExactOne) {
  // Clamping to [tmin, tmax] keeps t exact when the range ends on the triangle.
  const RayTriangleHit ends = intersect_ray_triangle(ray({0.25, 0.25, 1}, {0, 0, -1}, 0, 1), kTriangle);
  ASSERT_TRUE(ends.hit);
  EXPECT_LE(ends.t, 1);
  const RayTriangleHit starts = intersect_ray_triangle(ray({0.25, 0.25, 1}, {0, 0, -1}, 1, 2), kTriangle);
  ASSERT_TRUE(starts.hit);
  EXPECT_EQ(starts.t, 1);
}

TEST(IntersectRayTriangle, DegenerateTrianglesAreSegmentsAndPoints) {
  const Triangle segment{{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{2, 0, 0}}};  // collinear: the segment [0, 2] on x
  expect_hit_at(intersect_ray_triangle(ray({1.5, 1, 0}, {0, -1, 0}), segment), 1);
  expect_hit_at(intersect_ray_triangle(ray({2, 1, 1}, {0, -1, -1}), segment), 1);  // its end point
  expect_hit_at(intersect_ray_triangle(ray({-1, 0, 0}, {1, 0, 0}), segment), 1);   // along it
  expect_hit_at(intersect_ray_triangle(ray({3, 0, 0}, {-1, 0, 0}), segment), 1);   // along it, backwards
  expect_hit_at(intersect_ray_triangle(ray({1, 0, 0}, {0, 0, 1}), segment), 0);    // starting on it
  EXPECT_FALSE(intersect_ray_triangle(ray({1.5, 1, 1e-9}, {0, -1, 0}), segment).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray({2 + 1e-9, 1, 0}, {0, -1, 0}), segment).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray({-1, 1e-9, 0}, {1, 0, 0}), segment).hit);  // parallel beside it

  const Triangle repeated{{Vec3{0, 0, 0}, Vec3{0, 0, 0}, Vec3{0, 1, 0}}};  // a repeated vertex
  expect_hit_at(intersect_ray_triangle(ray({0, 0.5, 1}, {0, 0, -1}), repeated), 1);
  EXPECT_FALSE(intersect_ray_triangle(ray({1e-9, 0.5, 1}, {0, 0, -1}), repeated).hit);

  const Triangle point{{Vec3{1, 1, 1}, Vec3{1, 1, 1}, Vec3{1, 1, 1}}};
  expect_hit_at(intersect_ray_triangle(ray({0, 0, 0}, {1, 1, 1}), point), 1);
  expect_hit_at(intersect_ray_triangle(ray({3, 1, 1}, {-1, 0, 0}), point), 2);
  EXPECT_FALSE(intersect_ray_triangle(ray({0, 0, 0}, {1, 1, 1.000001}), point).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray({0, 0, 0}, {-1, -1, -1}), point).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray({0, 0, 0}, {1, 1, 1}, 0, 0.999), point).hit);
}

TEST(IntersectRayTriangle, ZeroDirectionTestsTheOriginAlone) {
  expect_hit_at(intersect_ray_triangle(ray({0.25, 0.25, 0}, {0, 0, 0}), kTriangle), 0);
  expect_hit_at(intersect_ray_triangle(ray({0.5, 0.5, 0}, {0, 0, 0}, 2, 3), kTriangle), 2);  // on an edge
  EXPECT_FALSE(intersect_ray_triangle(ray({0.25, 0.25, 1e-9}, {0, 0, 0}), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray({0.6, 0.6, 0}, {0, 0, 0}), kTriangle).hit);
  const Triangle segment{{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{2, 0, 0}}};
  expect_hit_at(intersect_ray_triangle(ray({1.5, 0, 0}, {0, 0, 0}), segment), 0);
  EXPECT_FALSE(intersect_ray_triangle(ray({1.5, 1e-9, 0}, {0, 0, 0}), segment).hit);
  const Triangle point{{Vec3{1, 1, 1}, Vec3{1, 1, 1}, Vec3{1, 1, 1}}};
  expect_hit_at(intersect_ray_triangle(ray({1, 1, 1}, {0, 0, 0}), point), 0);
  EXPECT_FALSE(intersect_ray_triangle(ray({1, 1, 1 + 1e-9}, {0, 0, 0}), point).hit);
}

TEST(IntersectRayTriangle, TinyAndHugeDirectionsAndScales) {
  for (int e : {-1000, -500, -60, 60, 500, 1000}) {
    const double s = std::ldexp(1.0, e);
    expect_hit_at(intersect_ray_triangle(ray({0.25, 0.25, 1}, {0, 0, -s}), kTriangle), 1 / s, 1e-13 / s);
    EXPECT_FALSE(intersect_ray_triangle(ray({0.25, 0.25, 1}, {0, 0, -s}, 0, 0.9 / s), kTriangle).hit);
  }
  for (int e : {-300, -100, 100, 300}) {  // the whole scene scaled
    const double s = std::ldexp(1.0, e);
    const Triangle big{{s * kTriangle.v[0], s * kTriangle.v[1], s * kTriangle.v[2]}};
    expect_hit_at(intersect_ray_triangle(ray(s * Vec3{0.5, 0, 1}, {0, 0, -1}), big), s, 1e-13 * s);
    EXPECT_FALSE(intersect_ray_triangle(ray(s * Vec3{0.5, -1e-9, 1}, {0, 0, -1}), big).hit);
  }
}

TEST(IntersectRayTriangle, OutOfContractInputsGiveNoHit) {
  const Vec3 o{0.25, 0.25, 1}, d{0, 0, -1};
  EXPECT_FALSE(intersect_ray_triangle(ray({kNan, 0.25, 1}, d), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray(o, {0, kNan, -1}), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray(o, d, kNan, 5), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray(o, d, 0, kNan), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray(o, {0, 0, -INFINITY}), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray({0.25, 0.25, INFINITY}, d), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray(o, d, 2, 1), kTriangle).hit);  // tmin > tmax
  EXPECT_FALSE(intersect_ray_triangle(ray(o, d, INFINITY, INFINITY), kTriangle).hit);
  EXPECT_FALSE(intersect_ray_triangle(ray(o, d, -INFINITY, -INFINITY), kTriangle).hit);
  Triangle bad = kTriangle;
  bad.v[1].y = kNan;
  EXPECT_FALSE(intersect_ray_triangle(ray(o, d), bad).hit);
  bad.v[1].y = -INFINITY;
  EXPECT_FALSE(intersect_ray_triangle(ray(o, d), bad).hit);
}

}  // namespace
}  // namespace cc
