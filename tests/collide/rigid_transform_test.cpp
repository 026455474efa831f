#include "collide/rigid_transform.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cc {
namespace {

Mat3 about_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Mat3::from_columns({c, s, 0}, {-s, c, 0}, {0, 0, 1});
}

TEST(RigidTransform, AppliesRotationThenTranslation) {
  const RigidTransform t{about_z(M_PI / 2), {10, 0, 0}};
  const Vec3 p = apply(t, {1, 0, 0});
  EXPECT_NEAR(p.x, 10, 1e-15);
  EXPECT_NEAR(p.y, 1, 1e-15);
}

TEST(RigidTransform, RelativeTakesBsFrameToAs) {
  const RigidTransform a{about_z(0.3), {1, 2, 3}}, b{about_z(-1.1), {-4, 5, 0.5}};
  const RigidTransform ab = relative(a, b);
  for (const Vec3& p : {Vec3{0, 0, 0}, Vec3{1, -2, 3}, Vec3{100, 7, -9}}) {
    // a (a^-1 b p) = b p
    const Vec3 via = apply(a, apply(ab, p)), direct = apply(b, p);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(via[k], direct[k], 1e-12);
  }
  EXPECT_EQ(relative(a, a).translation, (Vec3{0, 0, 0}));
}

TEST(RigidTransform, ErrorBoundGrowsWithMagnitudeAndTranslation) {
  const RigidTransform t{about_z(0.7), {3000, 0, 0}};
  EXPECT_GT(transform_error_bound(t, 6000), transform_error_bound(t, 1));
  EXPECT_LT(transform_error_bound(t, 6000), 1e-11);
}

}  // namespace
}  // namespace cc
