#include "oracle/exact/rational.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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
