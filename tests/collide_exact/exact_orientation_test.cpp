// orientation_sign and planar_orientation_sign against the sign of the determinant in GMP
// rationals (oracle/exact), on random nearly degenerate inputs: points on a plane (or a line)
// rounded and perturbed by 0..2 ulps, exponents spread over 2^-60..2^60 and over the whole range
// of doubles, subnormals. Every finite input must be decided, and decided right; so must each
// stage alone (the filter when it decides, the integers always).
#include "collide/exact_orientation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <string>

#include "oracle/exact/rational.h"
#include "test_random.h"

namespace cc {
namespace {

using exact::QVec3;
using exact::Rational;
using orientation_stages::exact_orientation_sign;
using orientation_stages::exact_planar_orientation_sign;
using orientation_stages::filtered_orientation_sign;
using orientation_stages::filtered_planar_orientation_sign;

using test::Random;

int sign_of(const Rational& q) { return sgn(q); }

int rational_orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const QVec3 qa = exact::rational(a);
  return sign_of(exact::dot(exact::rational(d) - qa, exact::cross(exact::rational(b) - qa, exact::rational(c) - qa)));
}

int rational_planar_orientation(const Vec3& a, const Vec3& b, const Vec3& c, int drop) {
  const QVec3 qa = exact::rational(a);
  return sign_of(exact::cross(exact::rational(b) - qa, exact::rational(c) - qa)[drop]);
}

std::string describe(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "a=(%a,%a,%a) b=(%a,%a,%a) c=(%a,%a,%a) d=(%a,%a,%a)", a.x, a.y, a.z, b.x, b.y, b.z, c.x,
                c.y, c.z, d.x, d.y, d.z);
  return buf;
}

struct Counts {
  int cases = 0, zero = 0, beyond_filter = 0;
};

// Checks both functions and both stages on (a, b, c, d) against the rationals.
void check(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, Counts& counts) {
  const int expected = rational_orientation(a, b, c, d);
  ++counts.cases;
  counts.zero += expected == 0;
  const std::optional<int> s = orientation_sign(a, b, c, d);
  ASSERT_TRUE(s.has_value()) << describe(a, b, c, d);
  ASSERT_EQ(*s, expected) << describe(a, b, c, d);
  ASSERT_EQ(exact_orientation_sign(a, b, c, d), expected) << describe(a, b, c, d);
  const std::optional<int> f = filtered_orientation_sign(a, b, c, d);
  if (f) {
    ASSERT_EQ(*f, expected) << describe(a, b, c, d);
  } else {
    ++counts.beyond_filter;
  }
}

void check_planar(const Vec3& a, const Vec3& b, const Vec3& c, int drop, Counts& counts) {
  const int expected = rational_planar_orientation(a, b, c, drop);
  ++counts.cases;
  counts.zero += expected == 0;
  const std::optional<int> s = planar_orientation_sign(a, b, c, drop);
  ASSERT_TRUE(s.has_value()) << describe(a, b, c, {}) << " drop " << drop;
  ASSERT_EQ(*s, expected) << describe(a, b, c, {}) << " drop " << drop;
  ASSERT_EQ(exact_planar_orientation_sign(a, b, c, drop), expected) << describe(a, b, c, {}) << " drop " << drop;
  const std::optional<int> f = filtered_planar_orientation_sign(a, b, c, drop);
  if (f) {
    ASSERT_EQ(*f, expected) << describe(a, b, c, {}) << " drop " << drop;
  } else {
    ++counts.beyond_filter;
  }
}

void report(const char* name, const Counts& c) {
  std::printf("%s: %d cases, %d exactly zero, %d beyond the filter\n", name, c.cases, c.zero, c.beyond_filter);
}

// Points of a random plane rounded to doubles, each perturbed by 0..2 ulps, at scales 2^-60..2^60
// and translations up to 2^60 (so the exponents of the coordinates span up to 2^-120..2^60).
TEST(ExactOrientationAgainstRationals, NearlyCoplanarPointsPerturbedByUlps) {
  Random r(11);
  Counts counts;
  for (int i = 0; i < 30000; ++i) {
    const double scale = std::ldexp(1.0, r.in(-60, 60));
    const Vec3 t = r.below(3) == 0 ? Vec3{} : std::ldexp(1.0, r.in(-60, 60)) * r.in_cube(1);
    const Vec3 a = t + scale * r.in_cube(1), b = t + scale * r.in_cube(1), c = t + scale * r.in_cube(1);
    const double s = r.between(-2, 2), u = r.between(-2, 2);
    const Vec3 d = a + s * (b - a) + u * (c - a);
    check(r.perturbed(a), r.perturbed(b), r.perturbed(c), r.perturbed(d), counts);
    if (testing::Test::HasFatalFailure()) return;
    check(a, b, c, r.perturbed(d), counts);
    if (testing::Test::HasFatalFailure()) return;
    // Nearly collinear: c on the line through a and b, perturbed.
    const Vec3 e = r.perturbed(a + s * (b - a));
    check(a, b, e, d, counts);
    if (testing::Test::HasFatalFailure()) return;
    for (int drop = 0; drop < 3; ++drop) {
      check_planar(a, b, e, drop, counts);
      if (testing::Test::HasFatalFailure()) return;
    }
  }
  report("near-coplanar", counts);
  EXPECT_GT(counts.beyond_filter, counts.cases / 20);
  EXPECT_GT(counts.zero, 100);
}

// Exactly coplanar lattices (z = p x + q y on integers times 2^k) rounded nowhere, then moved by
// one or two ulps, with k anywhere in the range of doubles, subnormals included.
TEST(ExactOrientationAgainstRationals, LatticePlanesAtEveryScale) {
  Random r(12);
  Counts counts, planar;
  for (int i = 0; i < 20000; ++i) {
    const int k = r.in(-1074, 1023 - 45);
    const int p = r.in(-4, 4), q = r.in(-4, 4);
    Vec3 v[4];
    for (Vec3& x : v) {
      const double px = r.in(-(1 << 20), 1 << 20), py = r.in(-(1 << 20), 1 << 20);
      x = {std::ldexp(px, k), std::ldexp(py, k), std::ldexp(p * px + q * py, k)};
    }
    if (r.below(2) == 0) v[3] = r.perturbed(v[3]);
    check(v[0], v[1], v[2], v[3], counts);
    if (testing::Test::HasFatalFailure()) return;
    for (int drop = 0; drop < 3; ++drop) {
      check_planar(v[0], v[1], v[3], drop, planar);
      if (testing::Test::HasFatalFailure()) return;
    }
  }
  report("lattice planes", counts);
  report("lattice planes, 2-D", planar);
  EXPECT_GT(counts.zero, counts.cases / 4);
  EXPECT_GT(counts.beyond_filter, counts.cases / 4);
}

// Every coordinate with its own exponent: over 2^-60..2^60, and over the whole range of doubles
// (subnormals, zeros and the largest values); some points derived from others as on a plane.
TEST(ExactOrientationAgainstRationals, WideExponentSpreads) {
  Random r(13);
  Counts counts;
  for (const auto& [lo, hi] : {std::pair{-60, 60}, std::pair{-1074, 1023}, std::pair{-1074, -1000}}) {
    for (int i = 0; i < 10000; ++i) {
      Vec3 v[4];
      for (Vec3& x : v) {
        for (int k = 0; k < 3; ++k) x[k] = r.below(10) == 0 ? 0.0 : std::ldexp(r.between(-1, 1), r.in(lo, hi));
      }
      if (r.below(2) == 0) {
        // d = a + s (b - a) + u (c - a) when that stays finite, perturbed.
        const Vec3 d = v[0] + r.unit() * (v[1] - v[0]) + r.unit() * (v[2] - v[0]);
        if (finite(d)) v[3] = r.perturbed(d);
      }
      if (r.below(4) == 0) v[3] = v[r.below(3)];  // coincident
      check(v[0], v[1], v[2], v[3], counts);
      if (testing::Test::HasFatalFailure()) return;
      for (int drop = 0; drop < 3; ++drop) {
        check_planar(v[0], v[1], v[3], drop, counts);
        if (testing::Test::HasFatalFailure()) return;
      }
    }
  }
  report("wide spreads", counts);
}

}  // namespace
}  // namespace cc
