#include "collide/box_features.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cc {
namespace {

TEST(Corners, EachCornerTakesTheSignsOfItsIndexBits) {
  const Obb b{{1, 2, 3}, {1, 2, 3}, Mat3::identity()};
  const auto c = corners(b);
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(c[i], (Vec3{i & 1 ? 2.0 : 0.0, i & 2 ? 4.0 : 0.0, i & 4 ? 6.0 : 0.0})) << i;
  }
}

TEST(Corners, OppositeCornersAreTheCentrePlusAndMinusOneOffset) {
  const double s = std::sqrt(0.5);
  const Mat3 turned = Mat3::from_columns({s, s, 0}, {-s, s, 0}, {0, 0, 1});
  const Obb b{{0.1, -7.3, 1e3}, {0.3, 1.7, 2.9}, turned};
  const auto c = corners(b);
  for (int i = 0; i < 8; ++i) {
    const Vec3 exact = (i & 1 ? 1 : -1) * b.half.x * b.axes.col[0] + (i & 2 ? 1 : -1) * b.half.y * b.axes.col[1] +
                       (i & 4 ? 1 : -1) * b.half.z * b.axes.col[2];
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[i][k] - b.center[k], exact[k], 1e-12) << i;
  }
  // About the origin, opposite corners are negatives of each other, bit for bit.
  const auto o = corners(Obb{{0, 0, 0}, {0.3, 1.7, 2.9}, turned});
  for (int i = 0; i < 8; ++i) EXPECT_EQ(o[7 - i], -o[i]) << i;
}

}  // namespace
}  // namespace cc
