#include "collide/sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace cc {
namespace {

TEST(TestSphereSphere, TouchingIsContact) {
  // Centres 5 apart along (3, 4, 0); radii 2 and 3.
  EXPECT_TRUE(test_sphere_sphere({{0, 0, 0}, 2}, {{3, 4, 0}, 3}));
  // Along (1, 2, 2): length 3.
  EXPECT_TRUE(test_sphere_sphere({{1, 1, 1}, 1.5}, {{2, 3, 3}, 1.5}));
}

TEST(TestSphereSphere, ApartBeyondTheBandIsNoContact) {
  EXPECT_FALSE(test_sphere_sphere({{0, 0, 0}, 2}, {{3, 4, 0}, 3 - 1e-12}));
  EXPECT_FALSE(test_sphere_sphere({{0, 0, 0}, 1}, {{2.5, 0, 0}, 1}));
}

TEST(TestSphereSphere, OverlappingConcentricAndPoints) {
  EXPECT_TRUE(test_sphere_sphere({{0, 0, 0}, 1}, {{0.5, 0, 0}, 1}));
  EXPECT_TRUE(test_sphere_sphere({{1, 2, 3}, 0}, {{1, 2, 3}, 5}));  // a point at the centre
  EXPECT_TRUE(test_sphere_sphere({{1, 2, 3}, 0}, {{1, 2, 3}, 0}));  // two equal points
  EXPECT_FALSE(test_sphere_sphere({{1, 2, 3}, 0}, {{1, 2, std::nextafter(3.0, 4.0)}, 0}));
  EXPECT_TRUE(test_sphere_sphere({{0, 0, 0}, 0}, {{0, 0, 1}, 1}));  // a point on the surface
}

TEST(TestSphereSphere, IsSymmetricBitForBit) {
  const Sphere a{{0.1, 0.2, 0.3}, 0.7}, b{{0.9, -0.4, 0.35}, 0.3};
  EXPECT_EQ(test_sphere_sphere(a, b), test_sphere_sphere(b, a));
}

// The squares as given decide as the scaled ones do: pairs moved along their line of centres to
// either side of the test's own first contact at unit scale (squares taken as given), then the
// same pairs scaled by 2^-520 and 2^520 (beyond [2^-900, 2^1020]: taken scaled) give the same
// answers, also with zero radii (points) and centres far from the origin.
TEST(TestSphereSphere, AsGivenAndScaledDecideAlikeAtTheBoundary) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(-1, 1), r(0, 0.8);
  const auto scaled = [](const Sphere& s, double k) { return Sphere{k * s.center, k * s.radius}; };
  int hits = 0, pairs = 0;
  for (int round = 0; round < 400; ++round) {
    const double offset = round % 4 == 0 ? 1e6 : 0;
    const Sphere a{{offset + u(rng), u(rng), u(rng)}, round % 5 == 0 ? 0.0 : r(rng)};
    const Sphere start{{offset + u(rng), u(rng), u(rng)}, round % 7 == 0 ? 0.0 : r(rng)};
    const Vec3 d = start.center - a.center;
    const auto at = [&](double s) { return Sphere{a.center + s * d, start.radius}; };
    double lo = 0, hi = 8;
    if (!test_sphere_sphere(a, at(lo)) || test_sphere_sphere(a, at(hi))) continue;
    for (int k = 0; k < 200 && std::nextafter(lo, hi) != hi; ++k) {
      (test_sphere_sphere(a, at((lo + hi) / 2)) ? lo : hi) = (lo + hi) / 2;
    }
    for (const Sphere& b : {at(lo), at(hi)}) {
      const bool expected = test_sphere_sphere(a, b);
      hits += expected, ++pairs;
      for (double k : {0x1p-520, 0x1p520}) EXPECT_EQ(test_sphere_sphere(scaled(a, k), scaled(b, k)), expected) << round;
    }
  }
  EXPECT_GT(pairs, 500);
  EXPECT_EQ(2 * hits, pairs);  // one inside and one outside the boundary each
}

TEST(TestSphereSphere, OutOfContractInputsGiveNoContact) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(test_sphere_sphere({{nan, 0, 0}, 1}, {{0, 0, 0}, 1}));
  EXPECT_FALSE(test_sphere_sphere({{0, 0, 0}, nan}, {{0, 0, 0}, 1}));
  EXPECT_FALSE(test_sphere_sphere({{0, 0, 0}, INFINITY}, {{0, 0, 0}, 1}));
  EXPECT_FALSE(test_sphere_sphere({{0, 0, 0}, -1}, {{0, 0, 0}, 3}));  // negative radius
}

}  // namespace
}  // namespace cc
