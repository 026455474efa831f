#include "collide/triangle_box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cc {
namespace {

const Aabb kBox{{0, 0, 0}, {1, 1, 1}};

Triangle tri(Vec3 a, Vec3 b, Vec3 c) { return {{a, b, c}}; }

TEST(TestTriangleAabb, TouchingAtACornerAnEdgeAndAFace) {
  EXPECT_TRUE(test_triangle_aabb(tri({1, 1, 1}, {2, 2, 1}, {2, 1, 2}), kBox));  // a corner only
  EXPECT_TRUE(test_triangle_aabb(tri({1.5, 0.5, 0.5}, {0.5, 1.5, 0.5}, {2, 2, 0.5}), kBox));  // a point of an edge
  EXPECT_TRUE(test_triangle_aabb(tri({0.25, 0.25, 1}, {3, 0.25, 1}, {0.25, 3, 1}), kBox));  // in the face's plane
}

TEST(TestTriangleAabb, ApartIsNoContact) {
  const double x = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(test_triangle_aabb(tri({x, 1, 1}, {2, 2, 1}, {2, 1, 2}), kBox));  // box axis: exact
  EXPECT_FALSE(test_triangle_aabb(tri({1.5 + 1e-9, 0.5 + 1e-9, 0.5}, {0.5 + 1e-9, 1.5 + 1e-9, 0.5}, {2, 2, 0.5}), kBox));
  EXPECT_FALSE(test_triangle_aabb(tri({0.25, 0.25, 1 + 1e-9}, {3, 0.25, 1 + 1e-9}, {0.25, 3, 1 + 1e-9}), kBox));
  // Separated by the triangle's normal only: a plane x + y + z = 3.5 cuts no corner.
  EXPECT_FALSE(test_triangle_aabb(tri({3.5, 0, 0}, {0, 3.5, 0}, {0, 0, 3.5}), kBox));
  EXPECT_TRUE(test_triangle_aabb(tri({3, 0, 0}, {0, 3, 0}, {0, 0, 3}), kBox));  // through (1,1,1)
}

TEST(TestTriangleAabb, DegenerateTriangles) {
  EXPECT_TRUE(test_triangle_aabb(tri({-1, 0.5, 0.5}, {2, 0.5, 0.5}, {0.5, 0.5, 0.5}), kBox));  // a segment through
  // A segment passing a vertical edge diagonally, 0.01 away: only e x z separates it.
  EXPECT_FALSE(test_triangle_aabb(tri({1.51, 0.51, 0.5}, {0.51, 1.51, 0.5}, {1.01, 1.01, 0.5}), kBox));
  EXPECT_TRUE(test_triangle_aabb(tri({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}), kBox));  // a point inside
  EXPECT_FALSE(test_triangle_aabb(tri({1.5, 0.5, 0.5}, {1.5, 0.5, 0.5}, {1.5, 0.5, 0.5}), kBox));
}

TEST(TestTriangleAabb, BoxesOfZeroExtent) {
  const Triangle t = tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_TRUE(test_triangle_aabb(t, {{0.25, 0.25, 0}, {0.25, 0.25, 0}}));  // a point on the triangle
  // A point in the triangle's plane but outside it: only an in-plane normal separates.
  EXPECT_FALSE(test_triangle_aabb(t, {{0.6, 0.6, 0}, {0.6, 0.6, 0}}));
  EXPECT_TRUE(test_triangle_aabb(t, {{0.5, 0.5, 0}, {0.5, 0.5, 0}}));  // on the hypotenuse
  // A flat box coplanar with a triangle whose edge x + y = 2.1 passes its corner (1,1).
  EXPECT_FALSE(test_triangle_aabb(tri({1.6, 0.5, 0}, {0.5, 1.6, 0}, {2, 2, 0}), {{0, 0, 0}, {1, 1, 0}}));
  EXPECT_TRUE(test_triangle_aabb(tri({1.5, 0.5, 0}, {0.5, 1.5, 0}, {2, 2, 0}), {{0, 0, 0}, {1, 1, 0}}));
  // A segment box crossing the triangle's plane outside the triangle.
  EXPECT_FALSE(test_triangle_aabb(t, {{0.6, 0.6, -1}, {0.6, 0.6, 2}}));
  EXPECT_TRUE(test_triangle_aabb(t, {{0.4, 0.4, -1}, {0.4, 0.4, 2}}));
}

TEST(TestTriangleAabb, OutOfContractInputsGiveNoContact) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(test_triangle_aabb(tri({nan, 0.5, 0.5}, {0.5, 0.5, 0.5}, {0.5, 0.6, 0.5}), kBox));
  EXPECT_FALSE(test_triangle_aabb(tri({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, {0.5, 0.6, 0.5}), {{0, 0, 0}, {1, -1, 1}}));
  EXPECT_FALSE(test_triangle_aabb(tri({0.5, 0.5, 0.5}, {INFINITY, 0.5, 0.5}, {0.5, 0.6, 0.5}), kBox));
}

TEST(TestTriangleObb, AgreesWithTheAabbTestForTheIdentityAndSignedPermutations) {
  const Triangle cases[] = {tri({1, 1, 1}, {2, 2, 1}, {2, 1, 2}), tri({3.5, 0, 0}, {0, 3.5, 0}, {0, 0, 3.5}),
                            tri({1.51, 0.51, 0.5}, {0.51, 1.51, 0.5}, {1.01, 1.01, 0.5})};
  const Obb identity{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, Mat3::identity()};
  const Obb permuted{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, Mat3::from_columns({0, -1, 0}, {0, 0, 1}, {-1, 0, 0})};
  for (const Triangle& t : cases) {
    EXPECT_EQ(test_triangle_obb(t, identity), test_triangle_aabb(t, kBox));
    EXPECT_EQ(test_triangle_obb(t, permuted), test_triangle_aabb(t, kBox));
  }
}

TEST(TestTriangleObb, RotatedBox) {
  // The unit cube rotated 45 degrees about z around its centre reaches 0.5 + sqrt(0.5) along x.
  const double c = std::sqrt(0.5);
  const Obb rotated{{0, 0, 0}, {0.5, 0.5, 0.5}, Mat3::from_columns({c, c, 0}, {-c, c, 0}, {0, 0, 1})};
  EXPECT_TRUE(test_triangle_obb(tri({c - 1e-9, -5, -5}, {c - 1e-9, 5, -5}, {c - 1e-9, 0, 5}), rotated));
  EXPECT_FALSE(test_triangle_obb(tri({c + 1e-9, -5, -5}, {c + 1e-9, 5, -5}, {c + 1e-9, 0, 5}), rotated));
  EXPECT_FALSE(test_triangle_obb(tri({0, 0, 0}, {0, 0, 0}, {0, 0, 0}), {{0, 0, 0}, {-1, 1, 1}, Mat3::identity()}));
}

}  // namespace
}  // namespace cc
