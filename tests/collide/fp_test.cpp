#include "collide/fp.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cc::fp {
namespace {

TEST(Sum3, DependsOnlyOnTheMultisetOfTerms) {
  // (1 + 2^53) + -2^53 = 0 but (1 + -2^53) + 2^53 = 1: plain summation depends on the order.
  const double a = 1, b = 0x1p53, c = -0x1p53;
  const double s = sum3(a, b, c);
  EXPECT_EQ(s, sum3(a, c, b));
  EXPECT_EQ(s, sum3(b, a, c));
  EXPECT_EQ(s, sum3(b, c, a));
  EXPECT_EQ(s, sum3(c, a, b));
  EXPECT_EQ(s, sum3(c, b, a));
}

TEST(Sum3, IsOddAndHomogeneous) {
  const double terms[][3] = {{1, 0x1p53, -0x1p53}, {0.1, 0.2, 0.3}, {1e16, 1, -1e16}, {3, -3, 0x1p-60}};
  for (const auto& t : terms) {
    EXPECT_EQ(sum3(-t[0], -t[1], -t[2]), -sum3(t[0], t[1], t[2]));
    EXPECT_EQ(sum3(0x1p7 * t[0], 0x1p7 * t[1], 0x1p7 * t[2]), 0x1p7 * sum3(t[0], t[1], t[2]));
  }
}

TEST(Sum3, IsExactForTwoTermsAndAZero) {
  EXPECT_EQ(sum3(0.1, 0.2, 0.0), 0.1 + 0.2);
  EXPECT_EQ(sum3(0.0, 0.1, 0.2), 0.1 + 0.2);
}

TEST(Sum3, StaysWithinTheErrorBoundOfOneOrder) {
  const double a = 0.1, b = 0.7, c = -0.3;
  const double s = sum3(a, b, c);
  EXPECT_LE(std::fabs(s - 0.5), 2 * u * (0.1 + 0.7 + 0.3));
}

TEST(Median3, PicksTheMiddleValue) {
  EXPECT_EQ(median3(1, 2, 3), 2);
  EXPECT_EQ(median3(3, 1, 2), 2);
  EXPECT_EQ(median3(2, 3, 1), 2);
  EXPECT_EQ(median3(5, 5, 1), 5);
}

TEST(Scale2, IsLdexpBitForBit) {
  const double values[] = {1.0, -1.5, 0.1, 0x1.fffffffffffffp0, 0x1p-1074, -0x1p-1060, 0x1.8p-1022, 0x1p1023,
                           1e300, -1e-300, 0.0, -0.0, INFINITY, -INFINITY};
  for (double x : values) {
    for (int e : {-1100, -1075, -1074, -1023, -1022, -600, -53, -1, 0, 1, 52, 600, 1022, 1023, 1024, 1100}) {
      const double got = scale2(x, e), want = std::ldexp(x, e);
      EXPECT_EQ(std::signbit(got), std::signbit(want)) << x << " * 2^" << e;
      EXPECT_EQ(got, want) << x << " * 2^" << e;  // rounding on underflow included
    }
  }
  EXPECT_TRUE(std::isnan(scale2(NAN, 3)));
}

TEST(ExponentOf, IsIlogbForNormalAndSubnormalValues) {
  for (double m : {1.0, 1.9999, 2.0, 0.75, -3.0, 0x1p-1022, 0x1p-1023, 0x1p-1074, 0x1.8p-1050, 1e308, -1e-310}) {
    EXPECT_EQ(exponent_of(m), std::ilogb(m)) << m;
  }
}

}  // namespace
}  // namespace cc::fp
