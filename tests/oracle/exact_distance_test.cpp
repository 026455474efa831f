// The exact distances (oracle/exact/exact_distance.h) on boxes whose answers are known: outside
// each kind of feature, inside, on the boundary, flat, skewed; and root_within at its ends.
#include "oracle/exact/exact_distance.h"

#include <gtest/gtest.h>

namespace cc::exact {
namespace {

const Obb kBox{{1, 1, 1}, {1, 2, 3}, Mat3::identity()};

QVec3 at(double x, double y, double z) { return rational(Vec3{x, y, z}); }

TEST(ExactDistance, OutsideAFaceAnEdgeAndACorner) {
  EXPECT_EQ(squared_distance_to_box(at(4, 1, 1), kBox), 4);       // 2 beyond the +x face
  EXPECT_EQ(squared_distance_to_box(at(5, 7, 1), kBox), 25);      // (3, 4) beyond the x-y edge
  EXPECT_EQ(squared_distance_to_box(at(-3, -5, 16), kBox), 169);  // (3, 4, 12) beyond a corner
  EXPECT_EQ(squared_distance_to_box(at(1.5, 0, 3), kBox), 0);     // inside
}

TEST(ExactDistance, DepthIsTheNearestFacesDistance) {
  EXPECT_TRUE(in_box(at(1.5, 2.5, 1), kBox));
  EXPECT_EQ(squared_depth_in_box(at(1.5, 2.5, 1), kBox), Rational(1, 4));  // 0.5 from +x and +y
  EXPECT_EQ(squared_depth_in_box(at(2, 0, 0), kBox), 0);                   // on the +x face
  const Obb plate{{0, 0, 0}, {1, 1, 0}, Mat3::identity()};
  EXPECT_TRUE(in_box(at(0.5, 0.5, 0), plate));
  EXPECT_EQ(squared_depth_in_box(at(0.5, 0.5, 0), plate), 0);
  EXPECT_FALSE(in_box(at(0.5, 0.5, 0x1p-1074), plate));
}

// Axes that are not orthonormal span a parallelepiped: a point beyond the face spanned by the
// second and third axes is as far as the plane of those two, not as far along the first axis.
TEST(ExactDistance, ASkewedBoxIsAParallelepiped) {
  const Obb skewed{{0, 0, 0}, {1, 1, 1}, Mat3::from_columns({1, 0, 0}, {1, 1, 0}, {0, 0, 1})};
  // The face q_0 = +1: the plane x - y = 1; the point (3, 0, 0) is (3 - 1)/sqrt(2) from it,
  // and its nearest point (2, 1, 0) lies on the face (q = (1, 1, 0)).
  EXPECT_EQ(squared_distance_to_box(at(3, 0, 0), skewed), 2);
  const QVec3 q = box_coordinates(at(1.5, 0.5, 0), skewed);
  EXPECT_EQ(q.x, 1);
  EXPECT_EQ(q.y, Rational(1, 2));
  EXPECT_EQ(squared_depth_in_box(at(1, 0.5, 0), skewed), Rational(1, 8));  // 0.5 from x - y = 1
  const Obb flat_axes{{0, 0, 0}, {1, 1, 1}, Mat3::from_columns({1, 0, 0}, {1, 0, 0}, {0, 0, 1})};
  EXPECT_THROW(box_coordinates(at(0, 0, 0), flat_axes), std::domain_error);
}

TEST(ExactDistance, RootWithinItsEnds) {
  EXPECT_TRUE(root_within(25, 4, 1));    // 5 in [3, 5]
  EXPECT_TRUE(root_within(9, 4, 1));     // 3 in [3, 5]
  EXPECT_FALSE(root_within(26, 4, 1));   // just beyond
  EXPECT_FALSE(root_within(8, 4, 1));    // just below
  EXPECT_TRUE(root_within(0, -1, 1));    // 0 in [-2, 0]
  EXPECT_FALSE(root_within(0, -2, 1));   // [-3, -1] holds no root
  EXPECT_TRUE(root_within(1, 0, 1));     // the lower end below 0
}

}  // namespace
}  // namespace cc::exact
