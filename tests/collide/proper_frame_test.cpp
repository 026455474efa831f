// proper_frame: a mirror-image frame gets a positive determinant and spans the same box; other
// frames stay as they are.
#include "collide/proper_frame.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cc {
namespace {

double det(const Mat3& m) { return dot(m.col[0], cross(m.col[1], m.col[2])); }

TEST(ProperFrame, AMirrorImageFrameLosesItsReflectionAndKeepsItsAxesUpToSign) {
  const Mat3 mirror = Mat3::from_columns({0, 1, 0}, {1, 0, 0}, {0, 0, 1});  // x and y swapped: det -1
  ASSERT_LT(det(mirror), 0);
  const Mat3 proper = proper_frame(mirror);
  EXPECT_GT(det(proper), 0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(proper.col[k] == mirror.col[k] || proper.col[k] == -mirror.col[k]) << k;
  }
}

TEST(ProperFrame, RotationsAndFramesWithoutASignStayAsTheyAre) {
  const Mat3 rotation = Mat3::from_columns({0, 1, 0}, {-1, 0, 0}, {0, 0, 1});
  EXPECT_EQ(proper_frame(rotation), rotation);
  const Mat3 flat = Mat3::from_columns({1, 0, 0}, {1, 0, 0}, {0, 0, 1});  // det 0
  EXPECT_EQ(proper_frame(flat), flat);
  const Mat3 nan = Mat3::from_columns({NAN, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_TRUE(std::isnan(proper_frame(nan).col[0].x));
}

}  // namespace
}  // namespace cc
