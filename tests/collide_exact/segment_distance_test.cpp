// distance_segment_segment against exact rational arithmetic (oracle/exact/exact_distance.h):
// for drawn pairs biased to crossing, parallel, collinear, nearly parallel, point segments and
// scales 2^-300 to 2^300, the distance lies within its bound of the exact one, each witness
// within its bound of its segment, and the witnesses as far apart as the distance says. The
// configurations are counted and each must be met.
#include "collide/segment_distance.h"

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

Vec3 integer_point(test::Random& r, int n) {
  return {double(r.in(-n, n)), double(r.in(-n, n)), double(r.in(-n, n))};
}

TEST(DistanceSegmentSegmentExact, WithinItsBounds) {
  test::Random r(47);
  std::map<std::string, int> met;
  for (int i = 0; i < 6000; ++i) {
    // Small integers times a power of two: crossing and parallel pairs are exact.
    const double unit = r.below(3) == 0 ? std::ldexp(1.0, r.in(-300, 300)) : 1.0;
    Segment a{unit * integer_point(r, 8), unit * integer_point(r, 8)};
    Segment b{unit * integer_point(r, 8), unit * integer_point(r, 8)};
    switch (r.below(8)) {
      case 0: {  // crossing at a common point
        const Vec3 common = unit * integer_point(r, 8), da = unit * integer_point(r, 3), db = unit * integer_point(r, 3);
        a = {common - da, common + 2 * da}, b = {common - 2 * db, common + db};
        break;
      }
      case 1: b.b = b.a + 0.5 * (a.b - a.a); break;  // parallel
      case 2: b = {a.a + 3 * (a.b - a.a), a.a + 5 * (a.b - a.a)}; break;  // collinear, apart
      case 3:  // nearly parallel: tilted by 2^-20 to 2^-50 of the scale
        b.b = b.a + (a.b - a.a);
        b.b.y += std::ldexp(unit, -r.in(20, 50));
        break;
      case 4: a.b = a.a; break;  // a point
      case 5: {  // nearly touching: b crosses near a's interior, 2^-10 to 2^-30 of their length away
        const double s = r.between(1, 1e3);
        a = {s * r.in_cube(1), s * r.in_cube(1)};
        const Vec3 c = a.a + r.between(0.1, 0.9) * (a.b - a.a), e = s * r.in_cube(1);
        const Vec3 w = unit_scaled(cross(a.b - a.a, e));
        const Vec3 off = std::ldexp(s, -r.in(10, 30)) * w;
        b = {c + off - r.between(0.1, 0.9) * e, c + off + r.between(0.1, 0.9) * e};
        ++met["nearly touching"];
        break;
      }
      default: {  // generic, with real coordinates
        const double s = r.between(1e-3, 1e3);
        a = {s * r.in_cube(1), s * r.in_cube(1)}, b = {s * r.in_cube(1), s * r.in_cube(1)};
        break;
      }
    }
    bool far = false;
    if (r.below(5) == 0) {  // far from the origin (2^10 to 2^40 times the scale): the witnesses round there
      const Vec3 offset = std::ldexp(unit, r.in(10, 40)) * Vec3{1, -1, 1};
      a = {a.a + offset, a.b + offset}, b = {b.a + offset, b.b + offset};
      far = true;
    }
    const Separation sep = distance_segment_segment(a, b);
    const Rational exact = exact::squared_distance_between_segments(a, b);
    ASSERT_TRUE(exact::root_within(exact, rational(sep.distance), rational(sep.distance_error)))
        << "case " << i << ": distance " << sep.distance << " error " << sep.distance_error << " exact^2 "
        << exact.get_d();
    const Rational pe2 = rational(sep.point_error) * rational(sep.point_error);
    ASSERT_LE(exact::squared_distance_to_segment(rational(sep.on_a), a), pe2) << i;
    ASSERT_LE(exact::squared_distance_to_segment(rational(sep.on_b), b), pe2) << i;
    const QVec3 w = rational(sep.on_b) - rational(sep.on_a);
    ASSERT_TRUE(exact::root_within(dot(w, w), rational(sep.distance),
                                   2 * rational(sep.point_error) + rational(sep.distance_error)))
        << i;
    const QVec3 da = rational(a.b) - rational(a.a), db = rational(b.b) - rational(b.a);
    const bool point = is_zero(da) || is_zero(db);
    ++met[exact == 0 ? "touching" : "apart"];
    if (!point && is_zero(cross(da, db))) ++met["parallel"];
    if (point) ++met["a point"];
    if (unit <= 0x1p-200) ++met["tiny"];
    if (far) ++met["far from the origin"];
    if (unit >= 0x1p200) ++met["huge"];
    // Tight: the bound is a few ULPs of the largest coordinate, not a fraction of it.
    const double scale = std::max({max_abs(a.a), max_abs(a.b), max_abs(b.a), max_abs(b.b)});
    if (sep.distance_error <= 0x1p-40 * scale) ++met["tight"];
  }
  for (const char* c : {"touching", "apart", "parallel", "a point", "tiny", "huge", "far from the origin", "nearly touching"}) {
    EXPECT_GT(met[c], 50) << c;
  }
  EXPECT_EQ(met["tight"], 6000) << "the bound is loose";
  for (const auto& [c, n] : met) std::cout << c << ": " << n << "\n";
}

// The gap along a direction is a lower bound on the distance whatever the direction: along the
// direction of the library's witnesses (nearly closest), that direction tilted by 2^-30 to
// 2^-50, a random one and the reversed one. Along the witnesses' direction it is also within
// 2^-40 of the scale of the exact distance, so it certifies something.
TEST(SegmentGapAlongExact, IsALowerBoundAndNearlyTheDistanceAlongTheWitnesses) {
  test::Random r(53);
  int tight = 0, apart = 0, above_zero = 0;
  for (int i = 0; i < 6000; ++i) {
    const double unit = r.below(3) == 0 ? std::ldexp(1.0, r.in(-300, 300)) : 1.0;
    Segment a{unit * integer_point(r, 8), unit * integer_point(r, 8)};
    Segment b{unit * integer_point(r, 8), unit * integer_point(r, 8)};
    if (r.below(3) == 0) b.b = b.a;  // a point: its nearest end is its only one
    const Separation sep = distance_segment_segment(a, b);
    const Rational exact = exact::squared_distance_between_segments(a, b);
    const Vec3 along = sep.on_b - sep.on_a;
    Vec3 tilted = along;
    tilted[r.below(3)] += std::ldexp(max_abs(along), -r.in(30, 50));
    for (const Vec3& direction : {along, tilted, r.in_cube(1), -1.0 * along}) {
      const double gap = segment_gap_along(a, b, direction);
      ASSERT_GE(gap, 0);
      ASSERT_TRUE(gap == 0 || rational(gap) * rational(gap) <= exact)
          << "case " << i << ": gap " << gap << " above the exact distance " << std::sqrt(exact.get_d());
      above_zero += gap > 0;
    }
    if (exact == 0) continue;
    ++apart;
    const double scale = std::max({max_abs(a.a), max_abs(a.b), max_abs(b.a), max_abs(b.b)});
    const double gap = segment_gap_along(a, b, along);
    tight += exact::root_within(exact, rational(gap), rational(0x1p-40 * scale));
  }
  EXPECT_EQ(tight, apart) << "the gap along the witnesses is not within 2^-40 of the distance";
  EXPECT_GT(above_zero, 6000);
}

}  // namespace
}  // namespace cc
