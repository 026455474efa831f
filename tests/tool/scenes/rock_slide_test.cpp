#include "tool/scenes/rock_slide.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cc::harness {
namespace {

TEST(RockSlide, IsDeterministicAndMovesEveryRockDownTheSlope) {
  RockSlide a({50, 3, 20}), b({50, 3, 20});
  ASSERT_EQ(a.size(), 50u);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a.pose_of(i), b.pose_of(i));
  std::vector<RigidTransform> before;
  for (std::size_t i = 0; i < a.size(); ++i) before.push_back(a.pose_of(i));
  a.step();
  int down = 0;
  for (std::size_t i = 0; i < a.size(); ++i) down += a.pose_of(i).translation.z < before[i].translation.z;
  EXPECT_GT(down, 45);  // all but rocks that wrapped to the top
}

TEST(RockSlide, PosesAreRotationsAndRocksShareAFewShapes) {
  RockSlide s({40, 1, 20});
  for (int frame = 0; frame < 30; ++frame) s.step();
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Mat3& r = s.pose_of(i).rotation;
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(dot(r.col[j], r.col[k]), j == k ? 1 : 0, 1e-14);
    }
    EXPECT_GT(dot(cross(r.col[0], r.col[1]), r.col[2]), 0);
  }
  EXPECT_LE(s.shapes().size(), 8u);
  EXPECT_EQ(s.mesh_of(0), s.shapes()[0]);
}

}  // namespace
}  // namespace cc::harness
