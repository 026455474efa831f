// orientation_sign and planar_orientation_sign on inputs whose sign is known by construction:
// exactly coplanar and collinear points the floating-point determinant misjudges, one-ulp
// perturbations, permutations and exact translations, extreme exponents, non-finite coordinates;
// both stages (the filter and the integers) exercised. (tests/collide_exact compares with GMP.)
#include "collide/exact_orientation.h"
#include "test_random.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <vector>

namespace cc {
namespace {

using orientation_stages::exact_orientation_sign;
using orientation_stages::exact_planar_orientation_sign;
using orientation_stages::filtered_orientation_sign;
using orientation_stages::filtered_planar_orientation_sign;

using test::Random;

// The determinant as a plain floating-point expression, for showing what it gets wrong.
double naive_determinant(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return dot(d - a, cross(b - a, c - a));
}
double naive_planar_determinant(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}
int sign(double x) { return (x > 0) - (x < 0); }

// A point of the plane z = p x + q y with x, y multiples of 2^-20 below 2^(bits - 20) (bits <= 48,
// |p|, |q| <= 4, so z is exact), its axes permuted by `perm` (the same for all points of a plane).
Vec3 lattice_point(Random& r, int p, int q, int bits, const std::array<int, 3>& perm) {
  const double x = static_cast<double>(r.integer(bits)) * 0x1p-20, y = static_cast<double>(r.integer(bits)) * 0x1p-20;
  const Vec3 v{x, y, p * x + q * y};
  Vec3 w;
  for (int k = 0; k < 3; ++k) w[perm[k]] = v[k];
  return w;
}

constexpr std::array<std::array<int, 3>, 6> kPermutations = {
    {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

TEST(ExactOrientation, SignConventionOnTheUnitSimplex) {
  const Vec3 o{0, 0, 0}, ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  // (b - a) x (c - a) = e_x x e_y = e_z: d = e_z is on its side.
  EXPECT_EQ(orientation_sign(o, ex, ey, ez), 1);
  EXPECT_EQ(orientation_sign(o, ex, ey, -1.0 * ez), -1);
  EXPECT_EQ(orientation_sign(o, ey, ex, ez), -1);
  // drop = i is component i of the cross product: e_y x e_z = e_x, e_z x e_x = e_y, e_x x e_y = e_z.
  EXPECT_EQ(planar_orientation_sign(o, ey, ez, 0), 1);
  EXPECT_EQ(planar_orientation_sign(o, ez, ex, 1), 1);
  EXPECT_EQ(planar_orientation_sign(o, ex, ey, 2), 1);
  EXPECT_EQ(planar_orientation_sign(o, ey, ex, 2), -1);
  // On small integers the cross product is exact: the three drops give its three signs.
  Random r(1);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 a{double(r.integer(10)), double(r.integer(10)), double(r.integer(10))};
    const Vec3 b{double(r.integer(10)), double(r.integer(10)), double(r.integer(10))};
    const Vec3 c{double(r.integer(10)), double(r.integer(10)), double(r.integer(10))};
    const Vec3 d{double(r.integer(10)), double(r.integer(10)), double(r.integer(10))};
    const Vec3 n = cross(b - a, c - a);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(planar_orientation_sign(a, b, c, k), sign(n[k]));
    EXPECT_EQ(orientation_sign(a, b, c, d), sign(naive_determinant(a, b, c, d)));  // exact here
  }
}

// Kettner et al.'s classroom example: (0.5 + k 2^-53, 0.5 + l 2^-53), (12, 12), (24, 24). The
// determinant is 12 (a.y - a.x), of sign l - k, which the plain expression often gets wrong.
TEST(ExactOrientation, NearlyCollinearGridThatTheFloatDeterminantMisjudges) {
  const Vec3 b{12, 12, 0}, c{24, 24, 0}, up{0, 0, 1};
  int naive_wrong = 0;
  for (int k = 0; k < 64; ++k) {
    for (int l = 0; l < 64; ++l) {
      const Vec3 a{0.5 + k * 0x1p-53, 0.5 + l * 0x1p-53, 0};
      const int expected = sign(l - k);
      ASSERT_EQ(planar_orientation_sign(a, b, c, 2), expected) << k << " " << l;
      ASSERT_EQ(planar_orientation_sign(b, c, a, 2), expected) << k << " " << l;
      // In 3-D: (b - a) x (c - a) is along z, d = (0, 0, 1) lies above a.
      ASSERT_EQ(orientation_sign(a, b, c, up), expected) << k << " " << l;
      naive_wrong += sign(naive_planar_determinant(a, b, c)) != expected;
    }
  }
  EXPECT_GT(naive_wrong, 100);  // what the exact signs are for
}

// Points of planes z = p x + q y with coordinates that are exact binary fractions of widely varying
// magnitudes: the determinant is 0, the floating-point one often is not.
TEST(ExactOrientation, ExactlyCoplanarBinaryFractions) {
  Random r(2);
  int naive_nonzero = 0, cases = 0;
  for (int i = 0; i < 20000; ++i) {
    const int p = r.below(9) - 4, q = r.below(9) - 4;
    const auto& perm = kPermutations[r.below(6)];
    std::array<Vec3, 4> v;
    for (Vec3& x : v) x = lattice_point(r, p, q, 1 + r.below(48), perm);
    ++cases;
    ASSERT_EQ(orientation_sign(v[0], v[1], v[2], v[3]), 0) << i;
    ASSERT_FALSE(filtered_orientation_sign(v[0], v[1], v[2], v[3])) << i;  // never a wrong sign
    naive_nonzero += naive_determinant(v[0], v[1], v[2], v[3]) != 0;
  }
  EXPECT_GT(naive_nonzero, cases / 10);
}

// A translation by 2^40 (+- 2^40 on the axes) with offsets that are multiples of 2^-10: coplanar,
// then one point moved off the plane by one unit of 2^-10 along z.
TEST(ExactOrientation, LargeTranslationsWithSmallOffsets) {
  Random r(3);
  const Vec3 t{0x1p40, -0x1p40, 0x1p40};
  for (int i = 0; i < 5000; ++i) {
    const int p = r.below(9) - 4, q = r.below(9) - 4;
    std::array<Vec3, 4> v;
    for (Vec3& x : v) {
      const Vec3 offset = 0x1p10 * lattice_point(r, p, q, 1 + r.below(28), kPermutations[0]);  // units 2^-10
      x = t + offset;  // exact: below 2^41 in units of 2^-10
    }
    ASSERT_EQ(orientation_sign(v[0], v[1], v[2], v[3]), 0) << i;
    // z = p x + q y + 2^40 + s 2^-10: the determinant is s 2^-10 times component z of the normal.
    const int nz = planar_orientation_sign(v[0], v[1], v[2], 2).value();
    const int s = r.below(2) == 0 ? 1 : -1;
    const Vec3 moved = v[3] + Vec3{0, 0, s * 0x1p-10};
    ASSERT_EQ(orientation_sign(v[0], v[1], v[2], moved), s * nz) << i;
  }
}

// d on the plane of a, b, c (z = p x + q y), then d.z moved by one or two ulps: the determinant is
// the displacement times component z of (b - a) x (c - a), computed exactly here (small lattice).
TEST(ExactOrientation, UlpPerturbationsHaveTheSignOfTheirDisplacement) {
  Random r(4);
  int exact_stage = 0;
  for (int i = 0; i < 20000; ++i) {
    const int p = r.below(9) - 4, q = r.below(9) - 4;
    const Vec3 a = lattice_point(r, p, q, 24, kPermutations[0]), b = lattice_point(r, p, q, 24, kPermutations[0]),
               c = lattice_point(r, p, q, 24, kPermutations[0]);
    Vec3 d = lattice_point(r, p, q, 1 + r.below(48), kPermutations[0]);
    const double nz = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);  // exact: below 2^53 units
    const int steps = 1 + r.below(2), direction = r.below(2) == 0 ? 1 : -1;
    for (int s = 0; s < steps; ++s) d.z = std::nextafter(d.z, direction * std::numeric_limits<double>::infinity());
    const int expected = direction * sign(nz);
    ASSERT_EQ(orientation_sign(a, b, c, d), expected) << i;
    ASSERT_EQ(orientation_sign(b, c, a, d), expected) << i;
    ASSERT_EQ(orientation_sign(a, c, b, d), -expected) << i;
    exact_stage += !filtered_orientation_sign(a, b, c, d).has_value();
  }
  EXPECT_GT(exact_stage, 1000);  // many are beyond the filter
}

TEST(ExactOrientation, CollinearAndCoincidentPointsGiveZero) {
  Random r(5);
  for (int i = 0; i < 5000; ++i) {
    // a + k v for small integers k, v with 2^-30 resolution: exactly collinear.
    const Vec3 a = r.in_cube(1000);
    const Vec3 v{static_cast<double>(r.integer(20)) * 0x1p-30, static_cast<double>(r.integer(20)) * 0x1p-30,
                 static_cast<double>(r.integer(20)) * 0x1p-30};
    const Vec3 a_lattice{std::ldexp(std::round(std::ldexp(a.x, 20)), -20), std::ldexp(std::round(std::ldexp(a.y, 20)), -20),
                         std::ldexp(std::round(std::ldexp(a.z, 20)), -20)};
    const Vec3 b = a_lattice + double(r.integer(8)) * v, c = a_lattice + double(r.integer(8)) * v;
    const Vec3 d = r.in_cube(1e6);
    ASSERT_EQ(orientation_sign(a_lattice, b, c, d), 0) << i;
    ASSERT_EQ(orientation_sign(d, a_lattice, b, c), 0) << i;
    for (int k = 0; k < 3; ++k) ASSERT_EQ(planar_orientation_sign(a_lattice, b, c, k), 0) << i;
    // Coincident points.
    ASSERT_EQ(orientation_sign(a, a, d, c), 0);
    ASSERT_EQ(orientation_sign(a, d, c, d), 0);
    ASSERT_EQ(orientation_sign(a, a, a, a), 0);
    ASSERT_EQ(planar_orientation_sign(a, d, d, 1), 0);
    ASSERT_EQ(planar_orientation_sign(a, d, a, 0), 0);
  }
  EXPECT_EQ(orientation_sign({}, {}, {}, {}), 0);
  EXPECT_EQ(planar_orientation_sign({}, {}, {}, 2), 0);
  // Projected points that coincide, distinct in 3-D.
  EXPECT_EQ(planar_orientation_sign({1, 2, 3}, {1, 2, 7}, {5, 5, 5}, 2), 0);
}

// Random inputs, many of them nearly degenerate: odd permutations negate the sign, even ones keep
// it.
TEST(ExactOrientation, SwappingTwoPointsNegatesTheSign) {
  Random r(6);
  for (int i = 0; i < 5000; ++i) {
    std::array<Vec3, 4> v;
    const int p = r.below(9) - 4, q = r.below(9) - 4;
    const auto& perm = kPermutations[r.below(6)];
    for (Vec3& x : v) x = lattice_point(r, p, q, 1 + r.below(48), perm);
    if (r.below(2) == 0) v[r.below(4)][r.below(3)] += 0x1p-20 * (r.below(2) == 0 ? 1 : -1);
    if (r.below(4) == 0) v[r.below(4)] = r.in_cube(1);
    const int s = orientation_sign(v[0], v[1], v[2], v[3]).value();
    EXPECT_EQ(orientation_sign(v[1], v[0], v[2], v[3]), -s);
    EXPECT_EQ(orientation_sign(v[2], v[1], v[0], v[3]), -s);
    EXPECT_EQ(orientation_sign(v[3], v[1], v[2], v[0]), -s);
    EXPECT_EQ(orientation_sign(v[0], v[2], v[1], v[3]), -s);
    EXPECT_EQ(orientation_sign(v[0], v[3], v[2], v[1]), -s);
    EXPECT_EQ(orientation_sign(v[0], v[1], v[3], v[2]), -s);
    EXPECT_EQ(orientation_sign(v[1], v[2], v[0], v[3]), s);
    EXPECT_EQ(orientation_sign(v[3], v[2], v[1], v[0]), s);
    for (int k = 0; k < 3; ++k) {
      const int t = planar_orientation_sign(v[0], v[1], v[2], k).value();
      EXPECT_EQ(planar_orientation_sign(v[1], v[0], v[2], k), -t);
      EXPECT_EQ(planar_orientation_sign(v[0], v[2], v[1], k), -t);
      EXPECT_EQ(planar_orientation_sign(v[2], v[1], v[0], k), -t);
      EXPECT_EQ(planar_orientation_sign(v[1], v[2], v[0], k), t);
    }
  }
}

// Lattice points (units of 2^-20, below 2^28) moved by lattice translations below 2^30: every sum
// is exact, and the sign does not change.
TEST(ExactOrientation, ExactTranslationKeepsTheSign) {
  Random r(7);
  int nonzero = 0;
  for (int i = 0; i < 5000; ++i) {
    std::array<Vec3, 4> v;
    const int p = r.below(9) - 4, q = r.below(9) - 4;
    const auto& perm = kPermutations[r.below(6)];
    for (Vec3& x : v) x = lattice_point(r, p, q, 1 + r.below(44), perm);
    if (r.below(2) == 0) v[r.below(4)][r.below(3)] += 0x1p-20 * (r.below(2) == 0 ? 1 : -1);
    const Vec3 t{static_cast<double>(r.integer(50)) * 0x1p-20, static_cast<double>(r.integer(50)) * 0x1p-20,
                 static_cast<double>(r.integer(50)) * 0x1p-20};
    const int s = orientation_sign(v[0], v[1], v[2], v[3]).value();
    nonzero += s != 0;
    ASSERT_EQ(orientation_sign(v[0] + t, v[1] + t, v[2] + t, v[3] + t), s) << i;
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(planar_orientation_sign(v[0] + t, v[1] + t, v[2] + t, k), planar_orientation_sign(v[0], v[1], v[2], k));
    }
  }
  EXPECT_GT(nonzero, 1000);
}

// Scaling by a power of two keeps the sign: the unit simplex at 2^k for k over the whole range of
// doubles, subnormals included, and with a huge and a tiny coordinate in one determinant.
TEST(ExactOrientation, ExtremeExponentsAreDecided) {
  for (int k = -1074; k <= 1023; ++k) {
    const double s = std::ldexp(1.0, k);
    const Vec3 o{0, 0, 0}, x{s, 0, 0}, y{0, s, 0}, z{0, 0, s};
    ASSERT_EQ(orientation_sign(o, x, y, z), 1) << k;
    ASSERT_EQ(orientation_sign(x, o, y, z), -1) << k;
    ASSERT_EQ(planar_orientation_sign(o, x, y, 2), 1) << k;
    // A translation by 1: (1 + s) is rounded for small s, so only the exact values matter.
    const Vec3 one{1, 1, 1};
    ASSERT_EQ(orientation_sign(one + o, one + x, one + y, one + z), (1 + s != 1 && s > 0) ? 1 : 0) << k;
  }
  const double big = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  const Vec3 o{0, 0, 0};
  // det = big^2 tiny: its floating-point evaluation overflows.
  EXPECT_EQ(orientation_sign(o, {big, 0, 0}, {0, big, 0}, {0, 0, tiny}), 1);
  EXPECT_EQ(orientation_sign(o, {big, 0, 0}, {0, big, 0}, {0, 0, -tiny}), -1);
  EXPECT_EQ(orientation_sign({-big, -big, -big}, {big, 0, 0}, {0, big, 0}, {big, big, big}), 1);
  // det = 2^1000 2^-540 2^-540 = 2^-80: the products of the minor underflow to zero.
  EXPECT_FALSE(filtered_orientation_sign(o, {0, 0x1p-540, 0}, {0, 0, 0x1p-540}, {0x1p1000, 0, 0}));
  EXPECT_EQ(orientation_sign(o, {0, 0x1p-540, 0}, {0, 0, 0x1p-540}, {0x1p1000, 0, 0}), 1);
  // The same underflow beside other terms: det[a; b; c] = 2^1000 2^-1080 - 2^459 2^-540 = 2^-81 > 0,
  // which the plain evaluation gets as -2^-81 with a permanent of 2^-81 (d = 0, so ours is -det).
  const Vec3 a{0x1p1000, 0x1p459, 0}, b{1, 0x1p-540, 0}, c{0, 0, 0x1p-540};
  EXPECT_EQ(orientation_sign(a, b, c, o), -1);
  EXPECT_EQ(orientation_sign(o, a, b, c), 1);
  EXPECT_FALSE(filtered_orientation_sign(a, b, c, o));
  EXPECT_EQ(planar_orientation_sign(o, {big, tiny, 0}, {-big, tiny, 0}, 2), 1);  // 2 big tiny, exact
  EXPECT_EQ(planar_orientation_sign({big, big, 0}, {-big, -big, 0}, {tiny, 0, 0}, 2), 1);  // 2 big tiny
  EXPECT_EQ(planar_orientation_sign({big, big, 0}, {tiny, 0, 0}, {-big, -big, 0}, 2), -1);
}

// Exponents of the coordinates spread over 2^-60..2^60 of each other (and beyond): always decided.
TEST(ExactOrientation, WideExponentSpreadsAreDecided) {
  Random r(8);
  for (int spread : {120, 400, 2097}) {
    for (int i = 0; i < 2000; ++i) {
      const int base = spread == 2097 ? -1074 : -spread / 2;
      std::array<Vec3, 4> v;
      for (Vec3& x : v) {
        for (int k = 0; k < 3; ++k) {
          const double m = r.between(-2, 2);
          x[k] = r.below(8) == 0 ? 0.0 : std::ldexp(m, base + r.below(spread));
        }
      }
      ASSERT_TRUE(orientation_sign(v[0], v[1], v[2], v[3]).has_value());
      ASSERT_EQ(orientation_sign(v[0], v[1], v[2], v[3]), exact_orientation_sign(v[0], v[1], v[2], v[3]));
      for (int k = 0; k < 3; ++k) ASSERT_TRUE(planar_orientation_sign(v[0], v[1], v[2], k).has_value());
    }
  }
}

TEST(ExactOrientation, NonFiniteCoordinatesGiveNullopt) {
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  for (double x : bad) {
    for (int k = 0; k < 12; ++k) {
      std::array<Vec3, 4> v = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
      v[k / 3][k % 3] = x;
      EXPECT_FALSE(orientation_sign(v[0], v[1], v[2], v[3])) << k;
      EXPECT_FALSE(filtered_orientation_sign(v[0], v[1], v[2], v[3])) << k;
      EXPECT_FALSE(exact_orientation_sign(v[0], v[1], v[2], v[3])) << k;
      if (k < 9) {
        for (int drop = 0; drop < 3; ++drop) {  // the dropped coordinate is not read
          EXPECT_EQ(planar_orientation_sign(v[0], v[1], v[2], drop).has_value(), k % 3 == drop) << k << " " << drop;
          EXPECT_EQ(exact_planar_orientation_sign(v[0], v[1], v[2], drop).has_value(), k % 3 == drop) << k << " " << drop;
        }
      }
    }
    // All four infinite in the same way: every difference is NaN.
    const Vec3 inf{x, x, x};
    EXPECT_FALSE(orientation_sign(inf, inf, inf, inf));
  }
  EXPECT_FALSE(planar_orientation_sign({}, {1, 0, 0}, {0, 1, 0}, 3));
  EXPECT_FALSE(planar_orientation_sign({}, {1, 0, 0}, {0, 1, 0}, -1));
}

// The filter decides random nondegenerate inputs; when it decides, the integers agree; exactly
// coplanar inputs are left to the integers.
TEST(ExactOrientation, BothStagesAreExercisedAndAgree) {
  Random r(9);
  int filtered = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Vec3 a = r.in_cube(1), b = r.in_cube(1), c = r.in_cube(1), d = r.in_cube(1);
    const std::optional<int> f = filtered_orientation_sign(a, b, c, d);
    const std::optional<int> e = exact_orientation_sign(a, b, c, d);
    ASSERT_TRUE(e.has_value());
    if (f) {
      ++filtered;
      ASSERT_EQ(*f, *e) << i;
    }
    for (int k = 0; k < 3; ++k) {
      const std::optional<int> fp = filtered_planar_orientation_sign(a, b, c, k);
      if (fp) {
        ASSERT_EQ(fp, exact_planar_orientation_sign(a, b, c, k));
      }
    }
  }
  EXPECT_GT(filtered, n * 99 / 100);
  const Vec3 a{0.25, 0.5, 0.75}, b{1, 2, 3}, c{-1, 0.5, 2};  // d = 3b - 2c + 0a, exactly
  const Vec3 d = 3.0 * b - 2.0 * c;
  EXPECT_FALSE(filtered_orientation_sign(a, b, c, d));
  EXPECT_EQ(exact_orientation_sign(a, b, c, d), 0);
}

}  // namespace
}  // namespace cc
