// distance_triangle_triangle against exact rational arithmetic (oracle/exact/exact_distance.h):
// for drawn pairs biased to parallel faces, vertices on faces, crossing and piercing, coplanar,
// degenerate triangles, far from the origin and scales 2^-300 to 2^300, the distance lies within
// its bound of the exact one, each witness within its bound of its triangle, the witnesses as far
// apart as the distance says, and the bound within 2^-40 of the largest coordinate. The
// configurations are counted and each must be met.
#include "collide/triangle_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "oracle/exact/exact_distance.h"
#include "test_random.h"

namespace cc {
namespace {

using exact::QVec3;
using exact::Rational;
using exact::rational;

Vec3 integer_point(test::Random& r, int n) { return {double(r.in(-n, n)), double(r.in(-n, n)), double(r.in(-n, n))}; }

Triangle moved(const Triangle& t, const Vec3& by) { return {{t.v[0] + by, t.v[1] + by, t.v[2] + by}}; }

// A drawn pair of triangles, on small integers times `unit`, and what configuration it is.
std::pair<Triangle, Triangle> draw_pair(test::Random& r, double unit, std::string& kind) {
  Triangle a{{unit * integer_point(r, 8), unit * integer_point(r, 8), unit * integer_point(r, 8)}};
  Triangle b{{unit * integer_point(r, 8), unit * integer_point(r, 8), unit * integer_point(r, 8)}};
  switch (r.below(8)) {
    case 0: kind = "parallel faces"; b = moved(a, unit * integer_point(r, 3)); break;
    case 1: {  // a vertex of b on a point of a (a vertex, an edge's midpoint, the centroid times 3)
      kind = "vertex on a";
      const Vec3 on = r.below(2) ? a.v[r.below(3)] : 0.5 * (a.v[0] + a.v[1]);
      b = moved(b, on - b.v[0]);
      break;
    }
    case 2: kind = "coplanar"; for (Vec3& v : b.v) v.z = 0; for (Vec3& v : a.v) v.z = 0; break;
    case 3: kind = "degenerate"; b.v[2] = r.below(2) ? b.v[0] : 0.5 * (b.v[0] + b.v[1]); break;
    case 5: {  // thin: b's third vertex 2^-8 to 2^-30 of the scale off its opposite edge
      kind = "thin";
      const Vec3 off{std::ldexp(unit, -r.in(8, 30)), std::ldexp(unit, -r.in(8, 30)), 0};
      b.v[2] = 0.5 * (b.v[0] + b.v[1]) + off;
      break;
    }
    case 4: {  // real coordinates
      kind = "generic";
      const double s = r.between(1e-3, 1e3);
      for (Vec3& v : a.v) v = s * r.in_cube(1);
      for (Vec3& v : b.v) v = s * r.in_cube(1);
      break;
    }
    default: kind = "integer"; break;
  }
  return {a, b};
}

TEST(DistanceTriangleTriangleExact, WithinItsBounds) {
  test::Random r(59);
  std::map<std::string, int> met;
  const int cases = 4000;
  for (int i = 0; i < cases; ++i) {
    // Mostly 1, else 2^-300..2^300, else tiny: 2^-560..2^-510, where products of four
    // coordinates underflow.
    const int draw = r.below(6);
    const double unit = draw == 0 ? std::ldexp(1.0, r.in(-560, -510))
                        : draw == 1 ? std::ldexp(1.0, r.in(-300, 300)) : 1.0;
    std::string kind;
    auto [a, b] = draw_pair(r, unit, kind);
    if (r.below(5) == 0) {  // far from the origin, where the witnesses round
      const Vec3 offset = std::ldexp(unit, r.in(10, 40)) * Vec3{1, -1, 1};
      a = moved(a, offset), b = moved(b, offset);
      ++met["far from the origin"];
    }
    const Separation sep = distance_triangle_triangle(a, b);
    const Rational exact = exact::squared_distance_between_triangles(a, b);
    ASSERT_TRUE(exact::root_within(exact, rational(sep.distance), rational(sep.distance_error)))
        << "case " << i << " (" << kind << "): distance " << sep.distance << " error " << sep.distance_error
        << " exact " << std::sqrt(exact.get_d());
    const Rational pe2 = rational(sep.point_error) * rational(sep.point_error);
    ASSERT_LE(exact::squared_distance_to_triangle(rational(sep.on_a), a), pe2) << i << " " << kind;
    ASSERT_LE(exact::squared_distance_to_triangle(rational(sep.on_b), b), pe2) << i << " " << kind;
    const QVec3 w = rational(sep.on_b) - rational(sep.on_a);
    ASSERT_TRUE(exact::root_within(dot(w, w), rational(sep.distance),
                                   2 * rational(sep.point_error) + rational(sep.distance_error)))
        << i;
    double scale = 0;
    for (int k = 0; k < 3; ++k) scale = std::max({scale, max_abs(a.v[k]), max_abs(b.v[k])});
    // Tight where the triangles are well shaped and products of their coordinates stay
    // normal; thin and tiny triangles are only held to their bound (counted, not asserted).
    const bool loose_allowed = kind == "thin" || unit < 0x1p-500;
    if (sep.distance_error <= 0x1p-40 * scale) {
      ++met["tight"];
    } else {
      EXPECT_TRUE(loose_allowed) << "case " << i << " (" << kind << "): a loose bound, " << sep.distance_error / scale
                                 << " of the scale; distance " << sep.distance << ", exact " << std::sqrt(exact.get_d());
      ++met["loose, thin or tiny"];
    }
    ++met[kind];
    ++met[exact == 0 ? "touching or meeting" : "apart"];
    if (unit <= 0x1p-200) ++met["tiny"];
    if (unit < 0x1p-500) ++met["below 2^-500"];
    if (unit >= 0x1p200) ++met["huge"];
  }
  for (const char* c : {"parallel faces", "vertex on a", "coplanar", "degenerate", "thin", "generic",
                        "touching or meeting", "apart", "tiny", "below 2^-500", "huge", "far from the origin"}) {
    EXPECT_GT(met[c], 50) << c;
  }
  for (const auto& [c, n] : met) std::cout << c << ": " << n << "\n";
}

// The gap along a direction is a lower bound on the distance, along the witnesses' direction,
// that direction tilted, a random one and the reversed one; along the witnesses', nearly the
// distance.
TEST(TriangleGapAlongExact, IsALowerBoundAndNearlyTheDistanceAlongTheWitnesses) {
  test::Random r(61);
  int apart = 0, tight = 0;
  for (int i = 0; i < 2000; ++i) {
    const double unit = r.below(3) == 0 ? std::ldexp(1.0, r.in(-300, 300)) : 1.0;
    std::string kind;
    const auto [a, b] = draw_pair(r, unit, kind);
    const Separation sep = distance_triangle_triangle(a, b);
    const Rational exact = exact::squared_distance_between_triangles(a, b);
    const Vec3 along = sep.on_b - sep.on_a;
    Vec3 tilted = along;
    tilted[r.below(3)] += std::ldexp(max_abs(along), -r.in(30, 50));
    for (const Vec3& direction : {along, tilted, r.in_cube(1), -1.0 * along}) {
      const double gap = triangle_gap_along(a, b, direction);
      ASSERT_TRUE(gap == 0 || rational(gap) * rational(gap) <= exact) << "case " << i << ": gap " << gap;
    }
    if (exact == 0 || kind == "thin") continue;  // thin: only held to be a lower bound
    ++apart;
    double scale = 0;
    for (int k = 0; k < 3; ++k) scale = std::max({scale, max_abs(a.v[k]), max_abs(b.v[k])});
    tight += exact::root_within(exact, rational(triangle_gap_along(a, b, along)), rational(0x1p-40 * scale));
  }
  EXPECT_EQ(tight, apart);
  EXPECT_GT(apart, 1000);
}

}  // namespace
}  // namespace cc
