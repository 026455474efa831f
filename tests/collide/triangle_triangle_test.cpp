#include "collide/triangle_triangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cc {
namespace {

Triangle tri(Vec3 a, Vec3 b, Vec3 c) { return {{a, b, c}}; }

const Triangle kBase = tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});

TEST(TestTriangleTriangle, TouchingAtAVertexAnEdgeAndCrossing) {
  EXPECT_TRUE(test_triangle_triangle(kBase, tri({0, 0, 0}, {-1, 0, 1}, {0, -1, 1})));          // shared vertex
  EXPECT_TRUE(test_triangle_triangle(kBase, tri({0.5, 0, 0}, {0.5, -1, 1}, {1.5, -1, 1})));    // vertex on an edge
  EXPECT_TRUE(test_triangle_triangle(kBase, tri({0.25, 0.25, -1}, {0.25, 0.25, 1}, {0.3, 0.2, 1})));  // piercing
}

TEST(TestTriangleTriangle, ParallelPlanesAndClearMisses) {
  EXPECT_FALSE(test_triangle_triangle(kBase, tri({0, 0, 1}, {1, 0, 1}, {0, 1, 1})));
  EXPECT_FALSE(test_triangle_triangle(kBase, tri({0, 0, 1e-9}, {1, 0, 1e-9}, {0, 1, 1e-9})));
  EXPECT_FALSE(test_triangle_triangle(kBase, tri({0.5, -1e-9, 0}, {0.5, -1, 1}, {1.5, -1, 1})));
}

TEST(TestTriangleTriangle, CoplanarTriangles) {
  EXPECT_TRUE(test_triangle_triangle(kBase, tri({0.25, 0.25, 0}, {1.25, 0.25, 0}, {0.25, 1.25, 0})));
  // Touching at a vertex on the hypotenuse, and apart: only an in-plane normal separates.
  EXPECT_TRUE(test_triangle_triangle(kBase, tri({0.5, 0.5, 0}, {1.5, 0.5, 0}, {0.5, 1.5, 0})));
  EXPECT_FALSE(test_triangle_triangle(kBase, tri({1, 1, 0}, {2, 1, 0}, {1, 2, 0})));
}

TEST(TestTriangleTriangle, DegenerateTriangles) {
  const Triangle segment = tri({0, 0, 0}, {1, 0, 0}, {0.5, 0, 0});
  EXPECT_TRUE(test_triangle_triangle(segment, tri({0.5, -1, 0}, {0.5, 1, 0}, {0.5, 0, 0})));  // crossing
  EXPECT_FALSE(test_triangle_triangle(segment, tri({0, 1, 0}, {1, 1, 0}, {0.5, 1, 0})));      // parallel, apart
  EXPECT_TRUE(test_triangle_triangle(segment, tri({0.5, 0, 0}, {2, 0, 0}, {1, 0, 0})));        // collinear overlap
  EXPECT_FALSE(test_triangle_triangle(segment, tri({2, 0, 0}, {3, 0, 0}, {2.5, 0, 0})));      // collinear apart
  const Triangle point = tri({0.25, 0.25, 0}, {0.25, 0.25, 0}, {0.25, 0.25, 0});
  EXPECT_TRUE(test_triangle_triangle(kBase, point));
  EXPECT_FALSE(test_triangle_triangle(kBase, tri({0.25, 0.25, 1e-3}, {0.25, 0.25, 1e-3}, {0.25, 0.25, 1e-3})));
  EXPECT_TRUE(test_triangle_triangle(point, point));
  EXPECT_FALSE(test_triangle_triangle(point, tri({0.25, 0.25, 1}, {0.25, 0.25, 1}, {0.25, 0.25, 1})));
}

TEST(TestTriangleTriangle, SubnormalEdgesStillGiveWellResolvedAxes) {
  // Found by the campaign: an edge of length 5e-324 made its cross products underflow, and a
  // clear separation (about 27 units) went unseen.
  const Triangle a = tri({0, -5e-324, -1.5e-323}, {8192, -5e-324, 0}, {4096, -5e-324, -1e-323});
  const Triangle b = tri({-30.112288320105705, -0.0, -7.778769097326427e-62},
                         {-30.112288320105705, -5e-324, -7.778769097326427e-62}, {4, -5e-324, 66.12370314431881});
  EXPECT_FALSE(test_triangle_triangle(a, b));
}

TEST(TestTriangleTriangle, IsSymmetricBitForBit) {
  const Triangle a = tri({0.1, 0.2, 0.3}, {1.1, -0.4, 0.2}, {0.3, 0.9, -0.5});
  const Triangle b = tri({0.5, 0.1, -0.2}, {0.6, 0.4, 0.8}, {-0.3, 0.2, 0.1});
  EXPECT_EQ(test_triangle_triangle(a, b), test_triangle_triangle(b, a));
}

TEST(TestTriangleTriangle, OutOfContractInputsGiveNoContact) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(test_triangle_triangle(kBase, tri({nan, 0, 0}, {1, 0, 0}, {0, 1, 0})));
  EXPECT_FALSE(test_triangle_triangle(kBase, tri({0.25, 0.25, -INFINITY}, {0.25, 0.25, 1}, {0.3, 0.2, 1})));
}

}  // namespace
}  // namespace cc
