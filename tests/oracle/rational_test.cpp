#include "oracle/exact/rational.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace cc::exact {
namespace {

TEST(Rational, IsTheExactValueOfADouble) {
  EXPECT_EQ(rational(0.1), Rational(3602879701896397, 36028797018963968));
  EXPECT_EQ(rational(-0.0), Rational(0));
  Rational tiny;
  mpq_set_ui(tiny.get_mpq_t(), 1, 1);
  mpq_div_2exp(tiny.get_mpq_t(), tiny.get_mpq_t(), 1074);
  EXPECT_EQ(rational(std::numeric_limits<double>::denorm_min()), tiny);
  EXPECT_THROW(rational(NAN), std::invalid_argument);
}

TEST(ToDouble, RoundsToNearest) {
  EXPECT_EQ(to_double(rational(0.1) + rational(0.2)), 0.1 + 0.2);
  EXPECT_EQ(to_double(Rational(1, 3)), 1.0 / 3.0);
  EXPECT_EQ(to_double(Rational(-2, 3)), -2.0 / 3.0);
}

// The rounding helpers against their definitions, computed directly: a rational q placed at the
// fraction k/n of the gap between a double x and the next one up, so that the doubles on either
// side of q, and which is nearer, are known without rounding anything. Over doubles of every
// kind: both signs, subnormals, the boundaries where the gap doubles (powers of two), the ends
// of the range, random ones; fractions 0, 1/n, ..., 1 with the tie 1/2.
struct Placed {
  Rational q;
  double below, above;  // the doubles around q: below <= q <= above, nothing between them
  int k, n;             // q = below + k/n (above - below)
};

std::vector<double> doubles_of_every_kind() {
  std::vector<double> xs = {0.0,
                            std::numeric_limits<double>::denorm_min(),
                            2 * std::numeric_limits<double>::denorm_min(),
                            std::numeric_limits<double>::min(),
                            std::nextafter(std::numeric_limits<double>::min(), 0.0),  // the largest subnormal
                            0x1p-1000,
                            0.1,
                            1.0,
                            std::nextafter(1.0, 0.0),
                            3.0,
                            0x1p52,
                            0x1p53,
                            std::nextafter(0x1p53, 0.0),
                            1e300,
                            std::nextafter(std::numeric_limits<double>::max(), 0.0)};
  std::mt19937_64 rng(20261122);
  for (int i = 0; i < 400; ++i) {
    const double m = 1 + static_cast<double>(rng() >> 12) * 0x1p-52;
    xs.push_back(std::ldexp(m, static_cast<int>(rng() % 2098) - 1074));
  }
  const std::size_t positive = xs.size();
  for (std::size_t i = 0; i < positive; ++i) xs.push_back(-xs[i]);  // the gap toward +inf from -x
  return xs;
}

std::vector<Placed> placed_rationals() {
  std::vector<Placed> out;
  for (double x : doubles_of_every_kind()) {
    const double up = std::nextafter(x, INFINITY);
    if (!std::isfinite(up) || !std::isfinite(x)) continue;
    const Rational gap = rational(up) - rational(x);
    for (int n : {2, 8, 1000}) {
      for (int k = 0; k <= n; ++k) {
        if (n > 8 && k > 3 && k < n - 3 && k != n / 2) continue;  // near the ends and the middle
        Rational fraction(k, n);
        fraction.canonicalize();  // gmpxx does not reduce k/n by itself
        out.push_back({rational(x) + fraction * gap, x, up, k, n});
      }
    }
  }
  return out;
}

bool even(double x) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  return (bits & 1) == 0;
}

TEST(RoundingHelpers, AreTheirDefinitions) {
  int ties = 0;
  for (const Placed& p : placed_rationals()) {
    const std::string where = std::to_string(p.k) + "/" + std::to_string(p.n) + " of the way from " +
                              std::to_string(p.below) + " (" + std::to_string(std::ilogb(p.below)) + ")";
    // The largest double <= q, the smallest double >= q.
    EXPECT_EQ(round_down(p.q), p.k == p.n ? p.above : p.below) << where;
    EXPECT_EQ(round_up(p.q), p.k == 0 ? p.below : p.above) << where;
    // The nearest, ties to the even significand.
    const double nearest = 2 * p.k < p.n ? p.below : (2 * p.k > p.n ? p.above : (even(p.below) ? p.below : p.above));
    EXPECT_EQ(to_double(p.q), nearest) << where;
    ties += 2 * p.k == p.n;
    // Each result is a double on the right side of q.
    EXPECT_LE(rational(round_down(p.q)), p.q) << where;
    EXPECT_GE(rational(round_up(p.q)), p.q) << where;
  }
  EXPECT_GT(ties, 800);
}

TEST(RoundingHelpers, BeyondTheRangeOfDoubles) {
  const double max = std::numeric_limits<double>::max();
  const Rational ulp = rational(max) - rational(std::nextafter(max, 0.0));  // 2^971
  Rational far = 1;
  mpq_mul_2exp(far.get_mpq_t(), far.get_mpq_t(), 1100);
  for (double sign : {1.0, -1.0}) {
    for (const auto& [past, nearest_is_max] :
         std::initializer_list<std::pair<Rational, bool>>{{ulp / 4, true},
                                                           {ulp / 2, false},  // a tie: DBL_MAX is odd, to infinity
                                                           {3 * ulp / 4, false},
                                                           {ulp, false},
                                                           {far, false}}) {
      const Rational q = Rational(sign) * (rational(max) + past);
      EXPECT_EQ(to_double(q), nearest_is_max ? sign * max : sign * INFINITY) << sign << " " << past.get_d();
      EXPECT_EQ(round_down(q), sign > 0 ? max : -INFINITY);
      EXPECT_EQ(round_up(q), sign > 0 ? INFINITY : -max);
    }
  }
  // Below the smallest subnormal: 0 on one side, +-2^-1074 on the other.
  const Rational tiny = rational(std::numeric_limits<double>::denorm_min()) / 1000;
  EXPECT_EQ(round_down(tiny), 0.0);
  EXPECT_EQ(round_up(tiny), std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(round_down(-tiny), -std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(round_up(-tiny), 0.0);
  EXPECT_EQ(to_double(tiny), 0.0);
}

// Magnitude::of(q) is q rounded to double precision as m 2^e, |m| in [1, 2), at any exponent.
TEST(Magnitude, IsTheRationalRoundedToDoublePrecisionAtAnyExponent) {
  for (const Placed& p : placed_rationals()) {
    if (std::fabs(p.below) < std::numeric_limits<double>::min() || std::fabs(p.above) < std::numeric_limits<double>::min()) {
      continue;  // to_double rounds subnormals to fewer bits
    }
    for (long shift : {0L, 3000L, -3000L}) {
      Rational shifted;
      if (shift >= 0) {
        mpq_mul_2exp(shifted.get_mpq_t(), p.q.get_mpq_t(), static_cast<unsigned long>(shift));
      } else {
        mpq_div_2exp(shifted.get_mpq_t(), p.q.get_mpq_t(), static_cast<unsigned long>(-shift));
      }
      const Magnitude m = Magnitude::of(shifted);
      const double expected = to_double(p.q);
      if (expected == 0) {
        EXPECT_EQ(m.m, 0);
        continue;
      }
      int e = 0;
      const double f = std::frexp(expected, &e);  // expected = f 2^e, |f| in [0.5, 1)
      EXPECT_EQ(m.m, 2 * f) << p.below << " shifted by " << shift;
      EXPECT_EQ(m.e, e - 1 + shift) << p.below << " shifted by " << shift;
    }
  }
}

TEST(Magnitude, NeitherUnderflowsNorOverflows) {
  const QVec3 tiny{rational(5e-324), 0, 0};
  const Magnitude l = length(tiny);
  EXPECT_EQ(l.to_double(), 5e-324);
  const Magnitude squared = l * l;  // 2^-2148: far below the double range
  EXPECT_EQ(squared.e, -2148);
  EXPECT_EQ((squared / l).to_double(), 5e-324);
  EXPECT_EQ(length(QVec3{3, 4, 0}).to_double(), 5);
  EXPECT_EQ(Magnitude::of(Rational(-3, 4)).to_double(), -0.75);
}

}  // namespace
}  // namespace cc::exact
