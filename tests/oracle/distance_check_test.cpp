// The exact check of a distance answer (oracle/exact/distance_check.h): each of its three checks
// refuses what it should and no more, on squares, for distances apart and signed ones; a distance
// without points; and the exact root rounded down.
#include "oracle/exact/distance_check.h"

#include <gtest/gtest.h>

#include <cmath>

#include "oracle/exact/exact_distance.h"

namespace cc::exact {
namespace {

using harness::DistanceClaim;

// A claim with points.
DistanceClaim claim(double d, Vec3 a, Vec3 b, double ed, double ep) { return {d, true, a, b, ed, ep}; }

// Two points: a at the origin, b at (3, 4, 0), distance 5.
const Triangle kPointA{{Vec3{0, 0, 0}, Vec3{0, 0, 0}, Vec3{0, 0, 0}}}, kPointB{{Vec3{3, 4, 0}, Vec3{3, 4, 0}, Vec3{3, 4, 0}}};
const auto kCheck = distance_check({Rational(25)}, boundary_of(kPointA), boundary_of(kPointB));

TEST(DistanceCheck, TakesARightAnswerAndRefusesEachWrongPart) {
  EXPECT_FALSE(kCheck(claim(5, {0, 0, 0}, {3, 4, 0}, 0, 0)).has_value());
  EXPECT_FALSE(kCheck(claim(5.5, {0, 0, 0}, {3, 4, 0}, 0.5, 0)).has_value());  // the distance at its tolerance
  EXPECT_NE(kCheck(claim(5.5, {0, 0, 0}, {3, 4, 0}, 0.25, 0))->find("distance 5.5"), std::string::npos);
  EXPECT_FALSE(kCheck(claim(5, {0, 0, 0.5}, {3, 4, 0}, 0.5, 0.5)).has_value());  // a point at its tolerance
  EXPECT_NE(kCheck(claim(5, {0, 0, 0.5}, {3, 4, 0}, 1, 0.25))->find("on_a lies"), std::string::npos);
  EXPECT_NE(kCheck(claim(5, {0, 0, 0}, {3, 4, 0.5}, 1, 0.25))->find("on_b lies"), std::string::npos);
  // Points on their shapes 5 apart, but a distance 4 said within 1: 5 - 4 = 1 <= 1 + 0, right;
  // within 0.5 it is not even the distance.
  EXPECT_FALSE(kCheck(claim(4, {0, 0, 0}, {3, 4, 0}, 1, 0)).has_value());
  EXPECT_TRUE(kCheck(claim(4, {0, 0, 0}, {3, 4, 0}, 0.5, 0)).has_value());
  EXPECT_NE(kCheck(claim(5, {0, 0, 0}, {3, 4, 0}, -1, 0))->find("error bounds"), std::string::npos);
  EXPECT_NE(kCheck(claim(5, {0, 0, 0}, {3, 4, 0}, 0, NAN))->find("error bounds"), std::string::npos);
  EXPECT_NE(kCheck(claim(NAN, {0, 0, 0}, {3, 4, 0}, 1, 1))->find("not finite"), std::string::npos);
  EXPECT_NE(kCheck(claim(5, {0, INFINITY, 0}, {3, 4, 0}, 1, 1))->find("not finite"), std::string::npos);
}

TEST(DistanceCheck, ADistanceWithoutPointsIsJudgedAlone) {
  // Points far off their shapes are not looked at when the claim gives none.
  EXPECT_FALSE(kCheck({5, false, {9, 9, 9}, {-9, -9, -9}, 0, 0}).has_value());
  EXPECT_NE(kCheck({6, false, {}, {}, 0.5, 0})->find("distance 6"), std::string::npos);
}

TEST(DistanceCheck, WitnessesTooFarApartAreRefused) {
  // Two segments 5 apart along x; points each on its segment but 9 apart: not a closest pair.
  const Triangle a{{Vec3{0, -9, 0}, Vec3{0, 9, 0}, Vec3{0, 9, 0}}}, b{{Vec3{5, -9, 0}, Vec3{5, 9, 0}, Vec3{5, 9, 0}}};
  const auto check = distance_check({Rational(25)}, boundary_of(a), boundary_of(b));
  EXPECT_FALSE(check(claim(5, {0, 0, 0}, {5, 0, 0}, 0, 0)).has_value());
  EXPECT_NE(check(claim(5, {0, 0, 0}, {5, 9, 0}, 0, 1))->find("points lie"), std::string::npos);
}

TEST(DistanceCheck, SignedDistancesOfBallsAndBoxes) {
  // Balls of radii 1 and 2, centres 5 apart: 2 apart; centres 1 apart: overlapping by 2.
  const Sphere a{{0, 0, 0}, 1}, b{{3, 4, 0}, 2}, near_b{{0.6, 0.8, 0}, 2};
  const auto apart = distance_check({Rational(25), 1, Rational(3)}, boundary_of(a), boundary_of(b));
  EXPECT_FALSE(apart(claim(2, {0.6, 0.8, 0}, {1.8, 2.4, 0}, 0, 0x1p-50)).has_value());  // 0.6 and 0.8 round
  EXPECT_TRUE(apart(claim(-2, {0.6, 0.8, 0}, {1.8, 2.4, 0}, 0, 0x1p-50)).has_value());  // the sign matters
  EXPECT_NE(apart(claim(2, {0, 0, 0}, {1.8, 2.4, 0}, 0, 0.5))->find("on_a lies"), std::string::npos);  // the centre
  const auto overlapping = distance_check({Rational(1), 1, Rational(3)}, boundary_of(a), boundary_of(near_b));
  // a's point (0.6, 0.8) and b's -(0.6, 0.8) are 2 apart; the same point twice is 0 apart.
  EXPECT_FALSE(overlapping(claim(-2, {0.6, 0.8, 0}, {-0.6, -0.8, 0}, 0, 0x1p-50)).has_value());
  EXPECT_NE(overlapping(claim(-2, {-0.6, -0.8, 0}, {-0.6, -0.8, 0}, 0, 0x1p-50))->find("points lie 0 apart"), std::string::npos);
  // A ball of radius 1 centred 0.5 deep in the unit box [-1, 1]^3 through its top face: -1.5.
  const Obb box{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
  const Sphere ball{{0, 0, 0.5}, 1};
  const auto inside = distance_check({Rational(1, 4), -1, Rational(1)}, boundary_of(ball), boundary_of(box));
  EXPECT_FALSE(inside(claim(-1.5, {0, 0, -0.5}, {0, 0, 1}, 0, 0)).has_value());
  EXPECT_NE(inside(claim(-1.5, {0, 0, -0.5}, {0, 0, 0.5}, 0, 0.25))->find("on_b lies"), std::string::npos);  // inside, not on the boundary
  EXPECT_EQ(rounded_down({Rational(1, 4), -1, Rational(1)}), -1.5);
  EXPECT_EQ(rounded_down({Rational(25), 1, Rational(3)}), 2);
  EXPECT_EQ(rounded_down({Rational(2)}), 1.4142135623730949);      // below the nearest double
  EXPECT_EQ(rounded_down({Rational(2), -1}), -1.4142135623730951);  // below -sqrt 2: the nearest
}

TEST(RoundedDown, IsExactWhereTheRootNearlyCancelsTheReach) {
  // sqrt(1 + 2^-100) - 1 = 2^-101 - 2^-203 + ...: just below 2^-101, far below an ulp of 1.
  const Rational squared = 1 + rational(0x1p-100);
  const double d = rounded_down({squared, 1, Rational(1)});
  EXPECT_LT(d, 0x1p-101);
  EXPECT_EQ(d, std::nextafter(0x1p-101, 0.0));
  // Touching: exactly 0; overlapping by a hair: the largest double below -2^-101 or so.
  EXPECT_EQ(rounded_down({Rational(1), 1, Rational(1)}), 0);
  EXPECT_LT(rounded_down({1 - rational(0x1p-100), 1, Rational(1)}), -0x1p-101);
  EXPECT_GT(rounded_down({1 - rational(0x1p-100), 1, Rational(1)}), -0x1p-100);
}

TEST(RoundedDown, ReturnsOnBallsNearlyTouchingFarFromTheOrigin) {
  // A campaign's balls near 1e57 whose reach cancels the centres' distance: the estimate is far
  // from the answer in ulps, which must be searched, not walked.
  const Vec3 ca{7.1074801150463116e+56, -3.364628508651572e+51, 1.7766227244369497e+57};
  const Vec3 cb{-4.67848024881873e+51, -3.364628508651572e+51, 6.011558091964263e+48};
  const QVec3 d = rational(cb) - rational(ca);
  const Rational reach = rational(1.9135197070042024e+57) + rational(2.2276301251307623e+47);
  const double down = rounded_down({dot(d, d), 1, reach});
  const auto at_most = [&](double x) {
    const Rational y = rational(x) + reach;
    return y <= 0 || y * y <= dot(d, d);
  };
  EXPECT_TRUE(at_most(down));
  EXPECT_FALSE(at_most(std::nextafter(down, INFINITY)));
}

TEST(RootDown, IsTheLargestDoubleWhoseSquareIsAtMostTheValue) {
  EXPECT_EQ(root_down(0), 0);
  EXPECT_EQ(root_down(4), 2);
  const double s = root_down(2);
  EXPECT_LE(rational(s) * rational(s), Rational(2));
  EXPECT_GT(rational(std::nextafter(s, 2.0)) * rational(std::nextafter(s, 2.0)), Rational(2));
  EXPECT_EQ(s, 1.4142135623730949);  // below the nearest double, 1.4142135623730951
  // Squares far outside the doubles: 2^-2000 and 2^2000.
  const Rational tiny = rational(0x1p-1000) * rational(0x1p-1000), huge = rational(0x1p1000) * rational(0x1p1000);
  EXPECT_EQ(root_down(tiny), 0x1p-1000);
  EXPECT_EQ(root_down(huge), 0x1p1000);
  EXPECT_EQ(root_down(tiny * 2), 0x1p-1000 * 1.4142135623730949);
  // A subnormal root, reached without stepping up from 0 ulp by ulp.
  EXPECT_EQ(root_down(rational(0x1p-1060) * rational(0x1p-1060)), 0x1p-1060);
}

}  // namespace
}  // namespace cc::exact
