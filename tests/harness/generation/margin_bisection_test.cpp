#include "harness/generation/margin_bisection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

const exact::ExactRationalReference kExact;

// A ball of radius 0.3 slid along x from the centre of a unit ball: they touch at s = 1.3, which
// no double is.
Input balls(double s) { return SphereSphereInput{{{0, 0, 0}, 1}, {{s, 0, 0}, 0.3}}; }

TEST(BisectToMargin, EndsOnAdjacentDoublesEitherSideOfTouching) {
  const auto in = bisect_to_margin(balls, 0, 0.5, 0, Side::inside, kExact);
  const auto out = bisect_to_margin(balls, 0, 0.5, 0, Side::outside, kExact);
  ASSERT_TRUE(in && out);
  EXPECT_EQ(*out, std::nextafter(*in, INFINITY));
  EXPECT_TRUE(kExact.judge(balls(*in)).answer.hit);
  EXPECT_FALSE(kExact.judge(balls(*out)).answer.hit);
  // From two apart cases: secant steps find the crossing first.
  EXPECT_EQ(bisect_to_margin(balls, 2, 1.9, 0, Side::inside, kExact), in);
}

TEST(BisectToMargin, ReachesAMarginOtherThanZero) {
  const double target = -0x1p-40;  // apart by 2^-40 of the scale (1.3)
  const auto s = bisect_to_margin(balls, 1, 2, target, Side::inside, kExact);
  ASSERT_TRUE(s);
  const double margin = kExact.judge(balls(*s)).margin;
  EXPECT_GE(margin, target);
  EXPECT_NEAR(margin, target, 0x1p-50);
}

TEST(BisectToMargin, GivesUpOutsideTheDomainOrWithoutACrossing) {
  const Family with_nan = [](double s) -> Input { return SphereSphereInput{{{0, 0, 0}, 1}, {{s, NAN, 0}, 0.3}}; };
  EXPECT_FALSE(bisect_to_margin(with_nan, 0, 1, 0, Side::inside, kExact));
  const Family concentric = [](double s) -> Input { return SphereSphereInput{{{0, 0, 0}, 1 + s * s}, {{0, 0, 0}, 0.3}}; };
  EXPECT_FALSE(bisect_to_margin(concentric, 0, 1, 0, Side::inside, kExact, 20));
}

}  // namespace
}  // namespace cc::harness
