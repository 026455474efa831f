// intersect_ray_triangle against an exact reference (GMP rationals, oracle/exact) on random rays
// and triangles: never later than the exact first hit, never a miss of an exact hit, and the
// reported point within the tolerance of the triangle.
#include "collide/ray_triangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <random>
#include <string>

#include "oracle/exact/exact_ray_triangle.h"
#include "oracle/exact/rational.h"
#include "test_random.h"

namespace cc {
namespace {

using exact::QVec3;
using exact::Rational;

using test::Random;

struct Statistics {
  int cases = 0, exact_hits = 0, hits = 0;
  double worst_distance = 0;  // the largest distance of a reported point from the triangle, over R
};

// Checks one case against the reference: an exact hit is reported, no later than exactly;
// a reported point lies within the tolerance of the triangle.
void check_against_exact(const Ray& r, const Triangle& tri, Statistics& stats) {
  const RayTriangleHit h = intersect_ray_triangle(r, tri);
  const exact::ExactRay q = exact::exact_ray(r);
  const std::array<QVec3, 3> v = exact::exact_triangle(tri);
  const std::optional<Rational> t_exact = exact::exact_first_hit(q, v);
  ++stats.cases;
  const auto describe = [&] {
    char buf[512];
    std::snprintf(buf, sizeof buf, "ray o=(%a,%a,%a) d=(%a,%a,%a) t=[%a,%a] tri=(%a,%a,%a)(%a,%a,%a)(%a,%a,%a)",
                  r.origin.x, r.origin.y, r.origin.z, r.dir.x, r.dir.y, r.dir.z, r.tmin, r.tmax, tri.v[0].x,
                  tri.v[0].y, tri.v[0].z, tri.v[1].x, tri.v[1].y, tri.v[1].z, tri.v[2].x, tri.v[2].y, tri.v[2].z);
    return std::string(buf);
  };
  if (t_exact) {
    ++stats.exact_hits;
    ASSERT_TRUE(h.hit) << "missed an exact hit at t = " << exact::to_double(*t_exact) << ": " << describe();
    ASSERT_LE(exact::rational(h.t), *t_exact) << "later than the exact t = " << exact::to_double(*t_exact) << ": "
                                              << describe();
  }
  if (!h.hit) return;
  ++stats.hits;
  ASSERT_GE(h.t, r.tmin);
  ASSERT_LE(h.t, r.tmax);
  if (!std::isfinite(h.t)) return;
  double reach = 0;
  for (const Vec3& p : tri.v) reach = std::max(reach, max_abs(p - r.origin));
  const Rational d2 = exact::distance2_to_triangle(q.at(exact::rational(h.t)), v);
  const Rational bound = exact::rational(kRayTriangleTolerance * reach);
  const double distance = std::sqrt(exact::to_double(d2));
  if (reach > 0) stats.worst_distance = std::max(stats.worst_distance, distance / reach);
  ASSERT_LE(d2, bound * bound) << "reported point " << distance << " away (R = " << reach << "): " << describe();
}

// A point of the triangle by barycentric weights (rounded), pushed off by `off` along `away`.
Vec3 point_of(const Triangle& t, double a, double b, const Vec3& away = {}, double off = 0) {
  const double c = 1 - a - b;
  return a * t.v[0] + b * t.v[1] + c * t.v[2] + off * away;
}

// A random triangle of one of several shapes: generic, sliver, cap, needle, segment, point.
Triangle random_triangle(Random& random, int kind) {
  const Vec3 a = random.in_cube(1), b = random.in_cube(1), w = random.in_cube(1);
  const double thin = std::ldexp(1.0, -random.below(60));
  switch (kind % 6) {
    case 0: return {{a, b, random.in_cube(1)}};
    case 1: return {{a, b, a + random.between(0, 1) * (b - a) + thin * w}};     // cap (thin, obtuse)
    case 2: return {{a, b, b + thin * w}};                                        // needle
    case 3: return {{a, b, a + 2 * (b - a)}};                                     // segment (nearly)
    case 4: return {{a, a, b}};                                                   // segment, repeated vertex
    default: return {{a, a + thin * w, a}};                                       // (nearly) a point
  }
}

TEST(IntersectRayTriangleExact, RandomRaysAimedAtAndNearTriangles) {
  Random random(20240611);
  Statistics stats;
  for (int i = 0; i < 6000; ++i) {
    const Triangle tri = random_triangle(random, i);
    const double x = random.unit(), y = random.between(0, 1 - x);
    const Vec3 target = point_of(tri, x, y, random.in_cube(1), i % 3 == 0 ? 0 : std::ldexp(1.0, -random.below(60)));
    const Vec3 origin = random.in_cube(i % 5 == 0 ? 1000 : 3);
    Ray r{origin, target - origin, 0, INFINITY};
    if (i % 4 == 1) r.tmax = random.between(0.9, 1.1);  // a segment ending near the triangle
    if (i % 7 == 2) r.tmin = -INFINITY;
    if (i % 7 == 3) r.dir = std::ldexp(1.0, random.below(80) - 40) * r.dir;
    check_against_exact(r, tri, stats);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(stats.exact_hits, 500);
  RecordProperty("worst_distance_log2", std::to_string(std::log2(stats.worst_distance)));
}

TEST(IntersectRayTriangleExact, ExactTouchesOnIntegerGrids) {
  // Small integers: the vertices, the ray and the touching points are exact, so edges,
  // vertices, coplanar and collinear configurations occur exactly.
  Random random(77);
  Statistics stats;
  for (int i = 0; i < 6000; ++i) {
    Triangle tri{{random.integer_point(4), random.integer_point(4), random.integer_point(4)}};
    if (i % 5 == 0) tri.v[2] = tri.v[0] + 2 * (tri.v[1] - tri.v[0]);  // collinear
    if (i % 11 == 0) tri.v[1] = tri.v[0];
    if (i % 3 == 0) tri.v[0].z = tri.v[1].z = tri.v[2].z = 0;            // in z = 0 (for the coplanar rays)
    // A target on a vertex, an edge (its midpoint, or a quarter) or inside.
    const int k = random.below(3);
    const Vec3 &p = tri.v[k], &q = tri.v[(k + 1) % 3];
    Vec3 target;
    switch (random.below(4)) {
      case 0: target = p; break;
      case 1: target = 0.5 * (p + q); break;
      case 2: target = 0.25 * (3 * p + q); break;
      default: target = 0.25 * (tri.v[0] + tri.v[1] + 2 * tri.v[2]); break;
    }
    Vec3 origin = random.integer_point(6);
    if (i % 3 == 0 && i % 2 == 0) origin.z = 0;  // coplanar with the z = 0 triangles
    Vec3 dir = target - origin;
    if (dir == Vec3{}) continue;
    if (random.below(4) == 0) dir = dir + Vec3{double(random.below(3) - 1), double(random.below(3) - 1), 0};
    Ray r{origin, dir, 0, INFINITY};
    switch (random.below(5)) {
      case 0: r.tmax = 1; break;            // ends on the target
      case 1: r.tmin = 1, r.tmax = 2; break;  // starts on it
      case 2: r.tmax = 0.75; break;
      case 3: r.tmin = -INFINITY; break;
      default: break;
    }
    check_against_exact(r, tri, stats);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(stats.exact_hits, 1000);
  RecordProperty("worst_distance_log2", std::to_string(std::log2(stats.worst_distance)));
}

TEST(IntersectRayTriangleExact, GrazingAndNearlyCoplanarRays) {
  Random random(4242);
  Statistics stats;
  for (int i = 0; i < 4000; ++i) {
    const Triangle tri = random_triangle(random, i % 3);  // generic, caps and needles
    const Vec3 n = cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0]);
    const double x = random.unit(), y = random.between(0, 1 - x);
    const Vec3 target = point_of(tri, x, y);
    // A direction in the plane (along an edge, turned a little) tilted by a tiny angle.
    const Vec3 along = tri.v[(i + 1) % 3] - tri.v[i % 3] + random.between(-0.1, 0.1) * (tri.v[(i + 2) % 3] - tri.v[i % 3]);
    const Vec3 dir = along + std::ldexp(random.between(-1, 1), -random.below(50)) * (1 / std::sqrt(dot(n, n) + 1e-300)) * n;
    const Vec3 origin = target - random.between(0.5, 2) * dir + std::ldexp(random.between(-1, 1), -random.below(50)) * n;
    check_against_exact({origin, dir, 0, INFINITY}, tri, stats);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(stats.exact_hits, 100);
  RecordProperty("worst_distance_log2", std::to_string(std::log2(stats.worst_distance)));
}

TEST(IntersectRayTriangleExact, WideScalesAndFarOrigins) {
  Random random(9);
  Statistics stats;
  for (int i = 0; i < 3000; ++i) {
    const double s = std::ldexp(1.0, random.below(400) - 200);
    Triangle tri = random_triangle(random, i % 4);
    for (Vec3& p : tri.v) p = s * p;
    const double x = random.unit(), y = random.between(0, 1 - x);
    const Vec3 target = point_of(tri, x, y);
    const Vec3 origin = target + std::ldexp(1.0, random.below(40)) * s * random.in_cube(1);
    check_against_exact({origin, target - origin, 0, INFINITY}, tri, stats);
    if (HasFatalFailure()) return;
  }
  RecordProperty("worst_distance_log2", std::to_string(std::log2(stats.worst_distance)));
}

}  // namespace
}  // namespace cc
