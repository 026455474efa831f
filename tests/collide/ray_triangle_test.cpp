#include "collide/ray_triangle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <string>

#include "oracle/exact/exact_ray_triangle.h"
#include "oracle/exact/rational.h"

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

// ---- Against an exact reference (GMP rationals) on random rays and triangles.

using exact::QVec3;
using exact::Rational;

// Doubles in [0, 1) from the raw 64-bit outputs (std's distributions differ between libraries).
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }
  double between(double lo, double hi) { return lo + (hi - lo) * unit(); }
  int below(int n) { return static_cast<int>(engine_() % static_cast<std::uint64_t>(n)); }
  Vec3 in_cube(double h) { return {between(-h, h), between(-h, h), between(-h, h)}; }
  Vec3 integer_point(int h) { return {double(below(2 * h + 1) - h), double(below(2 * h + 1) - h), double(below(2 * h + 1) - h)}; }

 private:
  std::mt19937_64 engine_;
};

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
