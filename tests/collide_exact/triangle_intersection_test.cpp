// intersect_triangles against the exact intersection (GMP rationals, oracle/exact): empty exactly
// when the exact intersection is, and the hull of its points within 2^-44 M kappa of the exact
// one both ways, on triangles drawn to touch, cross at grazing angles, share planes, be slivers,
// segments and points, at scales from 2^-1000 to 2^300.
#include "collide/triangle_intersection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "oracle/exact/exact_triangle_intersection.h"
#include "oracle/exact/rational.h"
#include "test_random.h"
#include "triangle_intersection_check.h"

namespace cc {
namespace {

using test::describe;


struct Met {
  int cases = 0, met = 0, touching = 0, coplanar_polygons = 0, grazing = 0, degenerate = 0;
  double worst = 0;  // the largest Hausdorff distance over its bound
};

void check(const Triangle& a, const Triangle& b, Met& met) {
  const TriangleIntersection r = intersect_triangles(a, b);
  const std::vector<exact::ExactCorner> corners = exact::exact_triangle_intersection(a, b);
  ++met.cases;
  ASSERT_EQ(r.empty(), corners.empty()) << describe(a, b);
  if (corners.empty()) return;
  ++met.met;
  const test::CornerDistance d = test::corner_distance(a, b, r, corners);
  met.touching += d.truth.size() == 1;
  met.coplanar_polygons += d.truth.size() >= 3;
  met.grazing += d.kappa > 1e3;
  met.worst = std::max(met.worst, d.distance / d.bound);
  ASSERT_LE(d.distance, d.bound) << "kappa " << d.kappa << ", said " << test::points_text(d.said) << ", exact "
                                 << test::points_text(d.truth) << ": " << describe(a, b);
}

Vec3 on_edge(const Triangle& t, int i, double s) { return t.v[i] + s * (t.v[(i + 1) % 3] - t.v[i]); }

// A pair drawn in one of the configurations the contract names.
std::pair<Triangle, Triangle> draw(test::Random& random, int kind, Met& met) {
  Triangle a, b;
  for (Vec3& p : a.v) p = random.in_cube(1);
  for (Vec3& p : b.v) p = random.in_cube(1);
  switch (kind) {
    case 0: break;                                // anywhere
    case 1: b.v[0] = a.v[random.below(3)]; break;  // a shared vertex
    case 2: b.v[1] = on_edge(a, random.below(3), random.unit()); break;  // a vertex on an edge (rounded)
    case 3: {  // integer grids: touching along edges and faces, coplanar pairs
      for (Vec3& p : a.v) p = random.integer_point(2);
      for (Vec3& p : b.v) p = random.integer_point(2);
      if (random.below(2) == 0) {
        for (Triangle* t : {&a, &b}) {
          for (Vec3& p : t->v) p.z = random.below(3) == 0 ? 1 : 0;
        }
      }
      break;
    }
    case 4: {  // coplanar on the tilted plane x + y + z = 3 (integer points), or one vertex off by ulps
      for (Triangle* t : {&a, &b}) {
        for (Vec3& p : t->v) {
          p.x = random.in(-4, 4);
          p.y = random.in(-4, 4);
          p.z = 3 - p.x - p.y;
        }
      }
      if (random.below(4) == 0) b.v[0] = random.perturbed(b.v[0]);
      break;
    }
    case 5: {  // grazing: b nearly in a's plane, crossing it at a small angle
      const double tilt = std::ldexp(1.0, -random.in(5, 40));
      for (int i = 0; i < 3; ++i) b.v[i] = a.v[random.below(3)] + 0.5 * random.in_cube(1);
      const Vec3 n = cross(a.v[1] - a.v[0], a.v[2] - a.v[0]);
      for (int i = 0; i < 3; ++i) {
        const double side = dot(b.v[i] - a.v[0], n) / dot(n, n);
        b.v[i] = b.v[i] - (side - (i == 0 ? tilt : -tilt)) * n;
      }
      break;
    }
    case 6: {  // slivers: a vertex near the opposite edge's line
      a.v[2] = random.perturbed(on_edge(a, 0, random.between(-0.5, 1.5)));
      b.v[2] = random.perturbed(on_edge(b, 0, random.between(-0.5, 1.5)));
      break;
    }
    case 7: {  // segments and points
      ++met.degenerate;
      a.v[2] = random.below(2) == 0 ? a.v[0] : on_edge(a, 0, 0.5);
      if (random.below(2) == 0) b.v[1] = b.v[2] = b.v[0];
      if (random.below(3) == 0) b.v[0] = on_edge(a, 0, 0.25);
      break;
    }
    case 9: {  // a tiny triangle (2^-20 .. 2^-1070 of b's size) at a vertex of b moved to the origin,
               // in the common plane y = 0 or not
      const Vec3 at = b.v[random.below(3)];
      const double grow = std::ldexp(1.0, random.in(0, 4));  // b's largest magnitude up to 32
      for (Vec3& p : b.v) p = grow * (p - at);
      // Half of them within a few subnormal steps (segments and points of subnormal length).
      const int e = -(random.below(2) == 0 ? random.in(1060, 1076) : random.in(20, 1076));
      const bool in_plane = random.below(2) == 0;
      for (Vec3& p : a.v) {
        const Vec3 d = random.in_cube(1);
        p = {std::ldexp(d.x, e), std::ldexp(d.y, e), std::ldexp(d.z, e)};
      }
      if (in_plane) {
        for (Triangle* t : {&a, &b}) {
          for (Vec3& p : t->v) p.y = 0;
        }
      }
      break;
    }
    default: {  // a moved by a few ulps: nearly coplanar, touching
      b = a;
      for (Vec3& p : b.v) p = random.perturbed(p);
      break;
    }
  }
  return {a, b};
}

// Found by the campaign: a triangle of subnormal size against a unit one in its plane. The
// crossing of a long edge with a tiny one was computed from products that underflowed to 0/0,
// and gave the long edge's end, 0.044 away; directions are now scaled to unit magnitude first.
TEST(IntersectTrianglesExactly, ATinyTriangleAgainstALargeOneInItsPlane) {
  const Triangle a = {{Vec3{-2e-323, 0, 0}, Vec3{0, 0, -2e-323}, Vec3{0, 0, 0}}};
  const Triangle b = {{Vec3{0, 0, 1}, Vec3{0, 0, 0}, Vec3{-0.03125, 0, -0.03125}}};
  Met met;
  check(a, b, met);
  check(b, a, met);
  for (int e : {-1, -40, -1000}) {  // the same at smaller scales of a
    Triangle small = a;
    for (Vec3& p : small.v) p = {std::ldexp(p.x, 1060 + e), 0, std::ldexp(p.z, 1060 + e)};
    check(small, b, met);
  }
  EXPECT_EQ(met.met, 5);
}

// Found by the campaign: a segment of subnormal length in the plane of a triangle whose largest
// coordinate is 2. Scaling the six vertices down to a largest magnitude in [1, 2) flushed the
// segment to a point, and the crossing became the end of the triangle's edge, 1 away; the
// vertices are now only ever scaled up.
TEST(IntersectTrianglesExactly, ASubnormalSegmentBesideALargerTriangleIsNotFlushed) {
  const Triangle a = {{Vec3{0, 0, 0}, Vec3{0, 0, 0}, Vec3{0, -5e-324, 0}}};
  const Triangle b = {{Vec3{0, 0, 1}, Vec3{0, -5e-324, -1}, Vec3{0, 1, -2}}};
  Met met;
  for (double s : {1.0, 0x1p10, 0x1p290}) {  // b's scale, a's kept
    Triangle big = b;
    for (Vec3& p : big.v) p = {p.x, p.y == -5e-324 ? p.y : s * p.y, s * p.z};
    check(a, big, met);
    check(big, a, met);
  }
  EXPECT_EQ(met.met, 6);
}

TEST(IntersectTrianglesExactly, AgreesWithTheExactIntersection) {
  test::Random random(2026);
  Met met;
  for (int i = 0; i < 15000; ++i) {
    auto [a, b] = draw(random, i % 11, met);
    const int e = i % 7 == 0 ? random.in(-1000, 300) : 0;  // far scales now and then
    for (Triangle* t : {&a, &b}) {
      for (Vec3& p : t->v) p = {std::ldexp(p.x, e), std::ldexp(p.y, e), std::ldexp(p.z, e)};
    }
    check(a, b, met);
    if (HasFatalFailure()) return;
  }
  std::printf("%d cases: %d meet, %d at a point, %d coplanar polygons, %d grazing (kappa > 1e3), %d degenerate; "
              "worst distance / bound %.3g\n",
              met.cases, met.met, met.touching, met.coplanar_polygons, met.grazing, met.degenerate, met.worst);
  EXPECT_GT(met.met, 6000);
  EXPECT_GT(met.touching, 1000);
  EXPECT_GT(met.coplanar_polygons, 500);
  EXPECT_GT(met.grazing, 200);
  EXPECT_GT(met.worst, 0);  // rounded corners were met
}

}  // namespace
}  // namespace cc
