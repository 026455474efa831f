#include "collide/sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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

TEST(TestSphereSphere, OutOfContractInputsGiveNoContact) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(test_sphere_sphere({{nan, 0, 0}, 1}, {{0, 0, 0}, 1}));
  EXPECT_FALSE(test_sphere_sphere({{0, 0, 0}, nan}, {{0, 0, 0}, 1}));
  EXPECT_FALSE(test_sphere_sphere({{0, 0, 0}, INFINITY}, {{0, 0, 0}, 1}));
  EXPECT_FALSE(test_sphere_sphere({{0, 0, 0}, -1}, {{0, 0, 0}, 3}));  // negative radius
}

}  // namespace
}  // namespace cc
