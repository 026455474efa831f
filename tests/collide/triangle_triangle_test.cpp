#include "collide/triangle_triangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "collide/simd.h"

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

TEST(TestTriangleTriangle, ASliverKeepsItsNormalWhenScalingFlushesItsLongEdges) {
  // b's first and third vertices are 2^-1074 apart in y: scaled down, its long edges lose their y
  // components and e0 x e1 comes out 0; the normal from the short edge (scaled up exactly) still
  // separates b from a, 0.13 of the largest coordinate away in the plane y = DBL_MIN.
  const double y = 2.225073858507201e-308, below = 2.2250738585072004e-308;
  const Triangle a = tri({0.03125, y, 1.25}, {0.014309717841332474, y, 8}, {-1, y, 8});
  const Triangle b = tri({8, below, 2}, {-0.6795751632047552, y, -0.011761275504420956}, {8, y, 2});
  EXPECT_FALSE(test_triangle_triangle(a, b));
  EXPECT_FALSE(test_triangle_triangle(b, a));
}

TEST(TestTriangleTriangle, IsSymmetricBitForBit) {
  const Triangle a = tri({0.1, 0.2, 0.3}, {1.1, -0.4, 0.2}, {0.3, 0.9, -0.5});
  const Triangle b = tri({0.5, 0.1, -0.2}, {0.6, 0.4, 0.8}, {-0.3, 0.2, 0.1});
  EXPECT_EQ(test_triangle_triangle(a, b), test_triangle_triangle(b, a));
}

// Random pairs, each also moved along the line of centroids to either side of the test's own
// first contact, where any difference in the rounding would show: every kernel this processor
// runs answers as the scalar one, and as with the triangles swapped.
TEST(TestTriangleTriangle, EveryKernelAnswersAlikeAtItsOwnBoundary) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto scalar = [](const Triangle& a, const Triangle& b) {
    const simd::ForcedKernel forced(simd::Kernel::scalar);
    return test_triangle_triangle(a, b);
  };
  const auto random_triangle = [&] {
    const Vec3 c{u(rng), u(rng), u(rng)};
    return tri(c + 0.6 * Vec3{u(rng), u(rng), u(rng)}, c + 0.6 * Vec3{u(rng), u(rng), u(rng)},
               c + 0.6 * Vec3{u(rng), u(rng), u(rng)});
  };
  const auto centroid = [](const Triangle& t) { return (1.0 / 3) * (t.v[0] + t.v[1] + t.v[2]); };
  int hits = 0, pairs = 0;
  for (int round = 0; round < 300; ++round) {
    const Triangle a = random_triangle(), start = random_triangle();
    const Vec3 d = centroid(start) - centroid(a);
    const auto at = [&](double s) {
      const Vec3 m = s * d - d;  // s = 0 puts the centroids together, 1 is the start
      return tri(start.v[0] + m, start.v[1] + m, start.v[2] + m);
    };
    double lo = 0, hi = 1;
    if (!scalar(a, at(lo)) || scalar(a, at(hi))) continue;
    for (int k = 0; k < 200 && std::nextafter(lo, hi) != hi; ++k) (scalar(a, at((lo + hi) / 2)) ? lo : hi) = (lo + hi) / 2;
    for (const Triangle& b : {start, at(lo), at(hi)}) {
      const bool expected = scalar(a, b);
      hits += expected, ++pairs;
      for (simd::Kernel kernel : simd::supported_kernels()) {
        const simd::ForcedKernel forced(kernel);
        EXPECT_EQ(test_triangle_triangle(a, b), expected) << to_string(kernel) << ", round " << round;
        EXPECT_EQ(test_triangle_triangle(b, a), expected) << to_string(kernel) << ", swapped, round " << round;
      }
    }
  }
  EXPECT_GT(pairs, 300);
  EXPECT_GT(hits, pairs / 4);
}

TEST(TestTriangleTriangle, OutOfContractInputsGiveNoContact) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(test_triangle_triangle(kBase, tri({nan, 0, 0}, {1, 0, 0}, {0, 1, 0})));
  EXPECT_FALSE(test_triangle_triangle(kBase, tri({0.25, 0.25, -INFINITY}, {0.25, 0.25, 1}, {0.3, 0.2, 1})));
}

}  // namespace
}  // namespace cc
