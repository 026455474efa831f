#include "collide/kdop_support.h"

#include <gtest/gtest.h>

#include <random>

#include "oracle/exact/rational.h"

namespace cc {
namespace {

using exact::Rational;

template <int K>
exact::QVec3 half_space_normal(int h) {
  const KdopDirection d = kdop_directions<K>()[h % (K / 2)];
  const int sign = h < K / 2 ? 1 : -1;
  return {sign * d.x, sign * d.y, sign * d.z};
}

// Directions that sit on the cones' boundaries (the normals themselves, sums and differences
// of two, tiny and huge components) and random ones.
std::vector<Vec3> directions() {
  std::vector<Vec3> out;
  const double values[] = {0, 1, -1, 0.5, -2, 0x1p-30, -0x1p-30, 3, 0x1p200, -0x1p-200};
  for (double x : values) {
    for (double y : values) {
      for (double z : values) out.push_back({x, y, z});
    }
  }
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int i = 0; i < 2000; ++i) out.push_back({uniform(random), uniform(random), uniform(random)});
  return out;
}

template <int K>
void expect_cones_combine_to_their_direction() {
  for (const Vec3& m : directions()) {
    const KdopCone<K> cone = kdop_cone<K>(m);
    exact::QVec3 sum{0, 0, 0};
    for (int j = 0; j < 3; ++j) {
      ASSERT_GE(cone.coefficient[j], 0) << "k = " << K;
      ASSERT_TRUE(cone.normal[j] >= 0 && cone.normal[j] < K);
      sum = sum + exact::rational(cone.coefficient[j]) * half_space_normal<K>(cone.normal[j]);
    }
    const Rational allowed = exact::rational(0x1p-46 * max_abs(m));
    const exact::QVec3 residual = exact::rational(m) - sum;
    for (int k = 0; k < 3; ++k) {
      ASSERT_LE(abs(residual[k]), allowed) << "k = " << K << ", m = " << m.x << " " << m.y << " " << m.z;
    }
  }
}

TEST(KdopCone, CombinesToItsDirectionWithNonNegativeCoefficients) {
  expect_cones_combine_to_their_direction<6>();
  expect_cones_combine_to_their_direction<14>();
  expect_cones_combine_to_their_direction<16>();
  expect_cones_combine_to_their_direction<18>();
  expect_cones_combine_to_their_direction<24>();
  expect_cones_combine_to_their_direction<26>();
}

TEST(KdopCone, ABoxUsesTheOctantWithExactCoefficients) {
  const KdopCone<6> c = kdop_cone<6>({-0.25, 3, -0x1p-40});
  EXPECT_EQ(c.normal, (std::array<int, 3>{1, 3, 5}));  // +y, -x, -z
  EXPECT_EQ(c.coefficient, (std::array<double, 3>{3, 0.25, 0x1p-40}));
}

// The bound is never below any point of the volume (here: the points the k-DOP was fitted to),
// in exact arithmetic up to support_bound's own rounding.
template <int K>
void expect_bounds_hold_the_points() {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> uniform(-4, 4);
  const std::vector<Vec3> dirs = directions();
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec3> points;
    for (int i = 0; i < 1 + trial % 7; ++i) points.push_back({uniform(random), uniform(random), uniform(random)});
    const Kdop<K> dop = fit_kdop<K>(points);
    for (std::size_t d = trial % 13; d < dirs.size(); d += 97) {
      const Vec3& m = dirs[d];
      const KdopCone<K> cone = kdop_cone<K>(m);
      const double bound = support_bound(dop, cone);
      double terms = 0;  // 3u sum c_j |bound_j| plus the residual's reach
      for (int j = 0; j < 3; ++j) terms += cone.coefficient[j] * 12;
      const Rational slack = exact::rational(3 * fp::u * terms + 0x1p-46 * max_abs(m) * 12);
      for (const Vec3& p : points) {
        ASSERT_LE(dot(exact::rational(m), exact::rational(p)), exact::rational(bound) + slack) << "k = " << K;
      }
    }
  }
}

TEST(SupportBound, HoldsEveryPointOfTheKdop) {
  expect_bounds_hold_the_points<6>();
  expect_bounds_hold_the_points<14>();
  expect_bounds_hold_the_points<16>();
  expect_bounds_hold_the_points<18>();
  expect_bounds_hold_the_points<24>();
  expect_bounds_hold_the_points<26>();
}

TEST(SupportBound, IsTheSupportOfABoxAndOfACubesEighteenDop) {
  const std::vector<Vec3> corners = {{-1, 2, 0}, {3, 4, 0.5}};
  const Kdop<6> box = fit_kdop<6>(corners);
  // Along (1, -2, 0.5): the corner (3, 2, 0.5) reaches 3 - 4 + 0.25.
  EXPECT_EQ(support_bound(box, kdop_cone<6>({1, -2, 0.5})), -0.75);
  std::vector<Vec3> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  const Kdop<18> dop = fit_kdop<18>(cube);
  // Along (1, 1, 1) the cube reaches 3 at (1, 1, 1), where its edge slabs x+y, y+z, z+x meet.
  EXPECT_NEAR(support_bound(dop, kdop_cone<18>({1, 1, 1})), 3, 1e-14);
  EXPECT_NEAR(support_bound(dop, kdop_cone<18>({-2, 1, 0.25})), 1.25, 1e-14);
}

}  // namespace
}  // namespace cc
