#include "collide/kdop_corners.h"

#include <gtest/gtest.h>

namespace cc {
namespace {

TEST(KdopCorners, AnAabbHasEightCorners) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 2, 3}};
  const auto c = kdop_corners(fit_kdop<6>(p));
  EXPECT_EQ(c.size(), 8u);
  EXPECT_EQ(c.front(), (Vec3{0, 0, 0}));
  EXPECT_EQ(c.back(), (Vec3{1, 2, 3}));
}

TEST(KdopCorners, ACubeSeenByAn18DopIsTheCube) {
  std::vector<Vec3> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  // The 18-DOP of a cube is the cube (its edge slabs touch it at its edges): 8 corners.
  EXPECT_EQ(kdop_corners(fit_kdop<18>(cube)).size(), 8u);
}

TEST(KdopCorners, CornersSpanTheDopOfATetrahedron) {
  const std::vector<Vec3> tet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Kdop<26> dop = fit_kdop<26>(tet);
  const auto c = kdop_corners(dop);
  ASSERT_GE(c.size(), 4u);
  // Refitting around the corners gives the same k-DOP up to the fit's outward rounding.
  const Kdop<26> again = fit_kdop<26>(c);
  for (int i = 0; i < 13; ++i) {
    EXPECT_NEAR(again.lo[i], dop.lo[i], 1e-12);
    EXPECT_NEAR(again.hi[i], dop.hi[i], 1e-12);
  }
}

TEST(KdopCorners, FlatAndEmptyDops) {
  // A point's 14-DOP is the point widened by the fit's outward rounding: a speck of corners.
  const std::vector<Vec3> point = {{1, 2, 3}};
  const auto speck = kdop_corners(fit_kdop<14>(point));
  ASSERT_FALSE(speck.empty());
  for (const Vec3& c : speck) EXPECT_LT(norm1(c - point[0]), 1e-13);
  EXPECT_EQ(kdop_corners(fit_kdop<6>(point)).size(), 1u);
  EXPECT_TRUE(kdop_corners(Kdop<18>{}).empty());
}

}  // namespace
}  // namespace cc
