// The exact check of a distance answer (oracle/exact/distance_check.h): each of its three checks
// refuses what it should and no more, on squares; and the exact root rounded down.
#include "oracle/exact/distance_check.h"

#include <gtest/gtest.h>

#include <cmath>

#include "oracle/exact/exact_distance.h"

namespace cc::exact {
namespace {

// Two points: a at the origin, b at (3, 4, 0), distance 5.
const auto kCheck = distance_check(
    Rational(25), [](const QVec3& p) { return dot(p, p); },
    [](const QVec3& p) {
      const QVec3 d = p - rational(Vec3{3, 4, 0});
      return dot(d, d);
    });

TEST(DistanceCheck, TakesARightAnswerAndRefusesEachWrongPart) {
  EXPECT_FALSE(kCheck(5, {0, 0, 0}, {3, 4, 0}, 0, 0).has_value());
  EXPECT_FALSE(kCheck(5.5, {0, 0, 0}, {3, 4, 0}, 0.5, 0).has_value());                      // the distance at its tolerance
  EXPECT_NE(kCheck(5.5, {0, 0, 0}, {3, 4, 0}, 0.25, 0)->find("distance 5.5"), std::string::npos);
  EXPECT_FALSE(kCheck(5, {0, 0, 0.5}, {3, 4, 0}, 0.5, 0.5).has_value());                    // a point at its tolerance
  EXPECT_NE(kCheck(5, {0, 0, 0.5}, {3, 4, 0}, 1, 0.25)->find("on_a lies 0.5"), std::string::npos);
  EXPECT_NE(kCheck(5, {0, 0, 0}, {3, 4, 0.5}, 1, 0.25)->find("on_b lies 0.5"), std::string::npos);
  // Points on their shapes 5 apart, but a distance 4 said within 1: 5 - 4 = 1 <= 1 + 0, right;
  // within 0.5 it is not even the distance.
  EXPECT_FALSE(kCheck(4, {0, 0, 0}, {3, 4, 0}, 1, 0).has_value());
  EXPECT_TRUE(kCheck(4, {0, 0, 0}, {3, 4, 0}, 0.5, 0).has_value());
  EXPECT_NE(kCheck(5, {0, 0, 0}, {3, 4, 0}, -1, 0)->find("error bounds"), std::string::npos);
  EXPECT_NE(kCheck(5, {0, 0, 0}, {3, 4, 0}, 0, NAN)->find("error bounds"), std::string::npos);
  EXPECT_NE(kCheck(NAN, {0, 0, 0}, {3, 4, 0}, 1, 1)->find("not finite"), std::string::npos);
  EXPECT_NE(kCheck(5, {0, INFINITY, 0}, {3, 4, 0}, 1, 1)->find("not finite"), std::string::npos);
}

TEST(DistanceCheck, WitnessesTooFarApartAreRefused) {
  // Two shapes 5 apart along x; points each within 1 of its shape but 9 apart: not a closest pair.
  const auto check = distance_check(
      Rational(25), [](const QVec3& p) { return p.x > 0 ? p.x * p.x : Rational(0); },
      [](const QVec3& p) { return p.x < 5 ? (5 - p.x) * (5 - p.x) : Rational(0); });
  EXPECT_FALSE(check(5, {0, 0, 0}, {5, 0, 0}, 0, 0).has_value());
  EXPECT_NE(check(5, {0, 0, 0}, {5, 9, 0}, 0, 1)->find("points lie"), std::string::npos);
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
