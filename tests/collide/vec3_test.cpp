#include "collide/vec3.h"

#include <gtest/gtest.h>

#include <limits>

namespace cc {
namespace {

TEST(Dot, IsTheSameForEveryOrderOfTheAxes) {
  const Vec3 a{1, 0x1p53, -0x1p53}, b{1, 1, 1};
  const double d = dot(a, b);
  EXPECT_EQ(d, dot({a.y, a.x, a.z}, {b.y, b.x, b.z}));
  EXPECT_EQ(d, dot({a.z, a.y, a.x}, {b.z, b.y, b.x}));
}

TEST(Cross, PermutesExactlyWithTheAxes) {
  const Vec3 a{0.1, 0.7, -0.3}, b{2.5, -1.25, 0.3};
  const Vec3 c = cross(a, b);
  // Swapping x and y is a reflection: the cross product's components are swapped and negated.
  const Vec3 s = cross({a.y, a.x, a.z}, {b.y, b.x, b.z});
  EXPECT_EQ(s.x, -c.y);
  EXPECT_EQ(s.y, -c.x);
  EXPECT_EQ(s.z, -c.z);
}

TEST(UnitScaled, BringsTheLargestComponentIntoOneToTwo) {
  const Vec3 tiny{5e-324, -1e-323, 0};
  const Vec3 s = unit_scaled(tiny);
  EXPECT_EQ(s.y, -1.0);
  EXPECT_EQ(s.x, 0.5);
  EXPECT_EQ(s.z, 0.0);
  EXPECT_EQ(unit_scaled(Vec3{}), Vec3{});
  EXPECT_EQ(unit_scaled(Vec3{6, 3, -1}), (Vec3{1.5, 0.75, -0.25}));
}

TEST(Finite, IsFalseForANaNOrAnInfinityInAnyComponentAndTrueForEveryFiniteValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const double finite_value : {0.0, -0.0, 1.0, -0x1.fffffffffffffp1023, 0x1.fffffffffffffp1023, 0x1p-1074}) {
    EXPECT_TRUE(finite(Vec3{finite_value, -finite_value, finite_value})) << finite_value;
    EXPECT_TRUE(finite(Mat3::from_columns({finite_value, 0, 0}, {0, finite_value, 0}, {0, 0, -finite_value})));
  }
  for (const double bad : {nan, -nan, inf, -inf}) {
    for (int i = 0; i < 3; ++i) {
      Vec3 v{1, 2, 3};
      v[i] = bad;
      EXPECT_FALSE(finite(v)) << bad << " at " << i;
      for (int column = 0; column < 3; ++column) {
        Mat3 m = Mat3::identity();
        m.col[column] = v;
        EXPECT_FALSE(finite(m)) << bad << " at " << i << " in column " << column;
      }
    }
  }
  EXPECT_FALSE(finite(Vec3{inf, -inf, 0}));  // infinities of both signs do not cancel
}

TEST(Mat3, TransposeTimesGivesCoordinatesAlongTheColumns) {
  const Mat3 m = Mat3::from_columns({0, 1, 0}, {0, 0, 1}, {1, 0, 0});
  EXPECT_EQ(transpose_times(m, {1, 2, 3}), (Vec3{2, 3, 1}));
  EXPECT_EQ((m * Vec3{1, 2, 3}), (Vec3{3, 1, 2}));
}

}  // namespace
}  // namespace cc
