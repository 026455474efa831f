#include "collide/kdop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace cc {
namespace {

TEST(KdopDirections, HaveKOverTwoSlabsInFclsOrder) {
  EXPECT_EQ(kdop_directions<6>().size(), 3u);
  EXPECT_EQ(kdop_directions<14>().size(), 7u);
  EXPECT_EQ(kdop_directions<16>().size(), 8u);
  EXPECT_EQ(kdop_directions<18>().size(), 9u);
  EXPECT_EQ(kdop_directions<24>().size(), 12u);
  EXPECT_EQ(kdop_directions<26>().size(), 13u);
  // FCL's N=24: the 18 ones, then (1,1,-1) (1,-1,1) (-1,1,1).
  const auto d = kdop_directions<24>();
  EXPECT_EQ(d[8].y, 1);
  EXPECT_EQ(d[8].z, -1);
  EXPECT_EQ(d[11].x, -1);
  EXPECT_TRUE(kdop_directions(12).empty());
}

TEST(FitKdop, SixDopIsTheBoundingBoxExactly) {
  const std::vector<Vec3> points = {{0.1, 0.2, 0.3}, {-1, 5, 0.3}, {2, -0.5, 7}};
  const Kdop<6> dop = fit_kdop<6>(points);
  EXPECT_EQ(dop.lo[0], -1);
  EXPECT_EQ(dop.hi[0], 2);
  EXPECT_EQ(dop.lo[1], -0.5);
  EXPECT_EQ(dop.hi[2], 7);
}

TEST(FitKdop, RoundsSumsOutward) {
  // 0.1 + 0.2 rounds up to 0.30000000000000004, which is above the exact sum; the fitted slab
  // must still contain the exact sum on both sides.
  const std::vector<Vec3> points = {{0.1, 0.2, 0}};
  const Kdop<18> dop = fit_kdop<18>(points);
  EXPECT_LE(dop.lo[3], 0.3);  // (1,1,0): 0.1 + 0.2 = 0.3000000000000000166... exactly
  EXPECT_GE(dop.hi[3], 0.30000000000000004);
}

TEST(TestKdopKdop, TouchingOnASlabOverlaps) {
  const std::vector<Vec3> a = {{0, 0, 0}, {1, 0, 0}};
  const std::vector<Vec3> b = {{1, 0, 0}, {2, 0, 0}};
  EXPECT_TRUE(test_kdop_kdop(fit_kdop<14>(a), fit_kdop<14>(b)));
  const std::vector<Vec3> apart = {{1.5, 0, 0}, {2, 0, 0}};
  EXPECT_FALSE(test_kdop_kdop(fit_kdop<14>(a), fit_kdop<14>(apart)));
}

TEST(TestKdopKdop, DiagonalSlabsSeparateWhatTheBoxesDoNot) {
  // The boxes [0,1]^2 and [1,2]x[1,2] touch at a corner; on the (1,1,0) slab the point sets
  // {(0,1),(1,0)} and {(1,2),(2,1)} project to [1,1] and [3,3]: the 18-DOP separates them.
  const std::vector<Vec3> a = {{0, 1, 0}, {1, 0, 0}};
  const std::vector<Vec3> b = {{1, 2, 0}, {2, 1, 0}};
  const std::vector<Vec3> corner_box = {{1, 1, 0}, {2, 2, 0}};
  EXPECT_TRUE(test_kdop_kdop(fit_kdop<6>(a), fit_kdop<6>(corner_box)));
  EXPECT_FALSE(test_kdop_kdop(fit_kdop<18>(a), fit_kdop<18>(b)));
}

TEST(TestKdopKdop, EmptyAndNonFiniteKdopsOverlapNothing) {
  const std::vector<Vec3> a = {{0, 0, 0}};
  EXPECT_FALSE(test_kdop_kdop(fit_kdop<18>(a), Kdop<18>{}));
  const std::vector<Vec3> nan = {{std::numeric_limits<double>::quiet_NaN(), 0, 0}, {0, 0, 0}};
  EXPECT_FALSE(test_kdop_kdop(fit_kdop<18>(a), fit_kdop<18>(nan)));
  const std::vector<Vec3> inf = {{INFINITY, 0, 0}, {0, 0, 0}};
  EXPECT_FALSE(test_kdop_kdop(fit_kdop<26>(a), fit_kdop<26>(inf)));
}

TEST(TestKdopKdop, IsSymmetric) {
  const std::vector<Vec3> a = {{0.1, 0.2, 0.3}, {0.5, -0.25, 1}};
  const std::vector<Vec3> b = {{0.4, 0.2, 0.9}};
  EXPECT_EQ(test_kdop_kdop(fit_kdop<24>(a), fit_kdop<24>(b)), test_kdop_kdop(fit_kdop<24>(b), fit_kdop<24>(a)));
}

}  // namespace
}  // namespace cc
