// Integers on a power of two: doubles placed exactly at every scale, and the roundings to a
// Magnitude the same as rational.h's on the same values, ties included.
#include "oracle/exact/dyadic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cc::exact {
namespace {

Rational on(const mpz_class& x, long exponent) {
  Rational q{x};
  if (exponent >= 0) {
    mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<unsigned long>(exponent));
  } else {
    mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<unsigned long>(-exponent));
  }
  return q;
}

TEST(Dyadic, EveryDoubleIsPlacedExactlyOnAnyLowerPowerOfTwo) {
  std::mt19937_64 random(5);
  for (const double x : {1.0, -1.0, 0.75, 3.0, 0x1p-1074, -0x1.8p-1070, 0x1.fffffffffffffp1023, 1e-300, 6.02e23}) {
    const long lowest = lowest_exponent(x);
    EXPECT_EQ(rational(x), on(mpz_class(rational(x) / on(1, lowest)), lowest)) << x;  // x / 2^lowest is an integer
    EXPECT_TRUE(mpz_class(rational(x) / on(1, lowest)) % 2 != 0) << x;                 // and odd
    for (const long below : {0L, 1L, 7L, 200L}) {
      mpz_class m;
      set_on(m, x, lowest - below);
      EXPECT_EQ(on(m, lowest - below), rational(x)) << x << " on 2^" << lowest - below;
    }
  }
  mpz_class zero{5};
  set_on(zero, 0.0, -3);
  EXPECT_EQ(sgn(zero), 0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double x = std::ldexp(std::uniform_real_distribution<double>(-1, 1)(random), static_cast<int>(trial % 2000) - 1000);
    if (x == 0) continue;
    mpz_class m;
    set_on(m, x, lowest_exponent(x) - 3);
    ASSERT_EQ(on(m, lowest_exponent(x) - 3), rational(x)) << x;
  }
}

TEST(Dyadic, RoundingsAreRationalsOwn) {
  std::mt19937_64 random(9);
  for (int trial = 0; trial < 5000; ++trial) {
    // Integers of 1 to 200 bits, some exactly halfway between two doubles (ties to even).
    const int bits = 1 + static_cast<int>(trial % 200);
    mpz_class x;
    for (int b = 0; b < bits; b += 32) {
      x <<= 32;
      x += static_cast<unsigned long>(random() & 0xffffffffu);
    }
    if (trial % 3 == 0 && bits > 60) {  // 53 bits, then a one, then zeros: a tie
      x >>= bits - 53;
      x = ((x << 1) + 1) << (bits - 54);
    }
    if (trial % 2) x = -x;
    const long exponent = static_cast<long>(trial % 301) - 150;
    const Magnitude got = nearest_magnitude(x, exponent), expected = Magnitude::of(on(x, exponent));
    ASSERT_EQ(got.m, expected.m) << trial;
    ASSERT_EQ(got.e, expected.e) << trial;
    // The length of the vector (x, 0, 0): |x| 2^exponent, through the square.
    const QVec3 v{on(x, exponent), 0, 0};
    const Magnitude l = length_from_square(x * x, exponent), lq = length(v);
    ASSERT_EQ(l.m, lq.m) << trial;
    ASSERT_EQ(l.e, lq.e) << trial;
  }
}

}  // namespace
}  // namespace cc::exact
