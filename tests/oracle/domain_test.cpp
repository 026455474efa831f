// The exact reference's domain checks at their boundaries, against the comparisons that define
// them: a scale exactly at 2^max_exponent is inside, one ulp above is outside; a frame whose
// Gram matrix is off by exactly the tolerance is orthonormal enough, one ulp more is not.
#include "oracle/exact/domain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "oracle/exact/rational.h"

namespace cc::exact {
namespace {

TEST(ScaleOutside, IsTheComparisonWithThePowersOfTwo) {
  std::mt19937_64 rng(3);
  for (const auto& [lo, hi] : {std::pair{-500, 500}, std::pair{-900, 1000}, std::pair{-300, 300}}) {
    const double top = std::ldexp(1.0, hi), bottom = std::ldexp(1.0, lo);
    std::vector<double> ms = {0.0, top, std::nextafter(top, INFINITY), std::nextafter(top, 0.0), bottom,
                              std::nextafter(bottom, 0.0), std::nextafter(bottom, INFINITY), 1.0,
                              std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min()};
    for (int i = 0; i < 200; ++i) ms.push_back(std::ldexp(1 + static_cast<double>(rng() >> 12) * 0x1p-52, static_cast<int>(rng() % 2000) - 1000));
    for (double m : ms) {
      Rational top_q = 1, bottom_q = 1;
      mpq_mul_2exp(top_q.get_mpq_t(), top_q.get_mpq_t(), static_cast<unsigned long>(hi));
      mpq_div_2exp(bottom_q.get_mpq_t(), bottom_q.get_mpq_t(), static_cast<unsigned long>(-lo));
      const bool outside = rational(m) > top_q || (m > 0 && rational(m) < bottom_q);
      EXPECT_EQ(scale_outside(m, lo, hi).has_value(), outside) << m << " in [2^" << lo << ", 2^" << hi << "]";
    }
  }
  EXPECT_EQ(scale_of(0.0), 1.0);
  EXPECT_EQ(scale_of(0x1p-1000), 0x1p-1000);
}

TEST(NotOrthonormal, IsTheGramMatrixWithinTheTolerance) {
  ASSERT_EQ(kObbOrthonormalTolerance, 0x1p-48);
  // |col 0|^2 - 1 = 2^-48 exactly: in; one ulp more on b: out.
  const double b = 0x1p-24;
  EXPECT_FALSE(not_orthonormal(Mat3::from_columns({1, b, 0}, {-b, 1, 0}, {0, 0, 1})).has_value());
  EXPECT_FALSE(not_orthonormal(Mat3::from_columns({1, 0, 0}, {0, 1, 0}, {0, 0, -1})).has_value());
  const double more = std::nextafter(b, 1.0);
  EXPECT_TRUE(not_orthonormal(Mat3::from_columns({1, more, 0}, {-more, 1, 0}, {0, 0, 1})).has_value());
  // An off-diagonal entry of exactly 2^-48: in; the next double: out.
  EXPECT_FALSE(not_orthonormal(Mat3::from_columns({1, 0, 0}, {0x1p-48, 1, 0}, {0, 0, 1})).has_value());
  EXPECT_TRUE(not_orthonormal(Mat3::from_columns({1, 0, 0}, {std::nextafter(0x1p-48, 1.0), 1, 0}, {0, 0, 1})).has_value());
  EXPECT_TRUE(not_orthonormal(Mat3::from_columns({1, 0, 0}, {0, 1, 0}, {0, 0, 1 + 0x1p-45})).has_value());
  EXPECT_FALSE(not_orthonormal(Mat3::from_columns({1, 0, 0}, {0, 1, 0}, {0, 0, 1 + 0x1p-50})).has_value());
}

TEST(SignedMargin, IsZeroOnlyForTouchingShapes) {
  EXPECT_EQ(signed_margin(0.25, 1), 0.25);
  EXPECT_EQ(signed_margin(-0.25, -1), -0.25);
  EXPECT_EQ(signed_margin(0.0, 1), 0x1p-1074);    // underflowed: the smallest subnormal, overlapping
  EXPECT_EQ(signed_margin(-0.0, -1), -0x1p-1074);  // underflowed: apart
  EXPECT_EQ(signed_margin(0.0, 0), 0.0);  // touching: 0, as rounded
  EXPECT_TRUE(std::signbit(signed_margin(-0.0, 0)));
}

}  // namespace
}  // namespace cc::exact
