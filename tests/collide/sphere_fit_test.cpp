#include "collide/sphere_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cc {
namespace {

const double kAboveOne = std::nextafter(1.0, 2.0);

TEST(DistanceUpperBound, IsTheDistanceRoundedUpByLittle) {
  const double d = distance_upper_bound({0, 0, 0}, {3, 4, 0});
  EXPECT_GE(d, 5);
  EXPECT_LE(d, 5 * (1 + 0x1p-46));
  EXPECT_EQ(distance_upper_bound({1, 2, 3}, {1, 2, 3}), 0);
  EXPECT_EQ(distance_upper_bound({1, 2, 3}, {3, 2, 1}), distance_upper_bound({3, 2, 1}, {1, 2, 3}));
}

TEST(DistanceUpperBound, NeitherUnderflowsNorOverflows) {
  // 5e-324 apart: the squares underflow, the scaled difference does not.
  EXPECT_GE(distance_upper_bound({0, 0, 0}, {5e-324, 0, 0}), 5e-324);
  const double tiny = distance_upper_bound({0, 0, 0}, {0x1p-600, 0x1p-600, 0});
  EXPECT_GE(tiny, 0x1p-600 * std::sqrt(2.0));
  EXPECT_LE(tiny, 0x1p-600 * std::sqrt(2.0) * (1 + 0x1p-45));
  const double huge = distance_upper_bound({-0x1p600, 0, 0}, {0x1p600, 0, 0});  // the squares overflow
  EXPECT_GE(huge, 0x1p601);
  EXPECT_LE(huge, 0x1p601 * (1 + 0x1p-46));
}

TEST(FitSphere, OnePointOrCoincidentPointsGiveRadiusZero) {
  const std::vector<Vec3> one = {{1.5, -2, 7}};
  EXPECT_EQ(fit_sphere(one), (Sphere{{1.5, -2, 7}, 0}));
  const std::vector<Vec3> same(5, Vec3{0.1, 0.2, 0.3});
  EXPECT_EQ(fit_sphere(same).radius, 0);
  EXPECT_EQ(fit_sphere(same).center, (Vec3{0.1, 0.2, 0.3}));
}

TEST(FitSphere, TwoPointsSpanADiameter) {
  const std::vector<Vec3> two = {{0, 0, 0}, {2, 0, 0}};
  const Sphere s = fit_sphere(two);
  EXPECT_EQ(s.center, (Vec3{1, 0, 0}));
  EXPECT_GE(s.radius, 1);
  EXPECT_LE(s.radius, 1 + 0x1p-46);
}

TEST(FitSphere, ACubesCornersGiveItsCircumscribedBall) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) corners.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  const Sphere s = fit_sphere(corners);
  EXPECT_EQ(s.center, (Vec3{0, 0, 0}));
  EXPECT_GE(s.radius, std::sqrt(3.0));
  EXPECT_LE(s.radius, std::sqrt(3.0) * (1 + 0x1p-46));
}

TEST(FitSphere, GrowsToTakeAPointOutsideTheFirstDiameter) {
  // The diameter from (-1, 0, 0) to (1, 0, 0) leaves (0, 1.5, 0) outside: Ritter's ball grows
  // to take it, and the radius holds every point.
  const std::vector<Vec3> points = {{-1, 0, 0}, {1, 0, 0}, {0, 1.5, 0}, {0, -0.25, 0.5}};
  const Sphere s = fit_sphere(points);
  for (const Vec3& p : points) EXPECT_LE(distance_upper_bound(p, s.center), s.radius);
  EXPECT_GT(s.radius, 1);
  EXPECT_LT(s.radius, 1.5);  // the smallest is 1.083: wider, but not the ball around the points' box
}

TEST(MergeSpheres, ABallInsideTheOtherGivesTheOther) {
  const Sphere big{{0, 0, 0}, 4}, small{{1, 1, 1}, 1};
  EXPECT_EQ(merge_spheres(big, small), big);
  EXPECT_EQ(merge_spheres(small, big), big);
  EXPECT_EQ(merge_spheres(big, big), big);
}

TEST(MergeSpheres, TwoBallsApartGiveTheBallAcrossBoth) {
  const Sphere a{{0, 0, 0}, 1}, b{{10, 0, 0}, 2};
  const Sphere m = merge_spheres(a, b);
  EXPECT_NEAR(m.center.x, 5.5, 1e-12);
  EXPECT_EQ(m.center.y, 0);
  EXPECT_GE(m.radius, 6.5);
  EXPECT_LE(m.radius, 6.5 * (1 + 0x1p-44));
  // Touching from inside on both sides, never short of it.
  EXPECT_GE(m.radius, distance_upper_bound(m.center, a.center) + a.radius);
  EXPECT_GE(m.radius, distance_upper_bound(m.center, b.center) + b.radius);
}

TEST(MergeSpheres, AlmostNestedBallsAreNotTakenAsNested) {
  // b reaches one ulp beyond a's surface: a does not hold it.
  const Sphere a{{0, 0, 0}, 1}, b{{0.5, 0, 0}, std::nextafter(0.5, 1.0)};
  const Sphere m = merge_spheres(a, b);
  EXPECT_NE(m, a);
  EXPECT_GE(m.radius, kAboveOne);
}

}  // namespace
}  // namespace cc
