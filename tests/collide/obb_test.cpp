#include "collide/obb.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "collide/simd.h"

namespace cc {
namespace {

Obb box(Vec3 center, Vec3 half, Mat3 axes = Mat3::identity()) { return {center, half, axes}; }

Mat3 about_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Mat3::from_columns({c, s, 0}, {-s, c, 0}, {0, 0, 1});
}

const Obb kUnit = box({0, 0, 0}, {1, 1, 1});

TEST(TestObbObb, FaceContactIsContact) {
  EXPECT_TRUE(test_obb_obb(kUnit, box({2, 0, 0}, {1, 1, 1})));
  EXPECT_TRUE(test_obb_obb(kUnit, box({2, 2, 2}, {1, 1, 1})));  // corner to corner
  EXPECT_TRUE(test_obb_obb(kUnit, kUnit));
}

TEST(TestObbObb, ApartBeyondTheBandIsNoContact) {
  EXPECT_FALSE(test_obb_obb(kUnit, box({2 + 1e-9, 0, 0}, {1, 1, 1})));
  // Rotated 45 degrees about z, B reaches sqrt(2) along x.
  const Mat3 r = about_z(M_PI / 4);
  EXPECT_FALSE(test_obb_obb(kUnit, box({1 + std::sqrt(2.0) + 1e-9, 0, 0}, {1, 1, 1}, r)));
  EXPECT_TRUE(test_obb_obb(kUnit, box({1 + std::sqrt(2.0) - 1e-9, 0, 0}, {1, 1, 1}, r)));
}

TEST(TestObbObb, ZeroExtentsArePointsSegmentsAndRectangles) {
  EXPECT_TRUE(test_obb_obb(kUnit, box({1, 0.5, 0}, {0, 0, 0})));   // a point on a face
  EXPECT_FALSE(test_obb_obb(kUnit, box({1.5, 0, 0}, {0, 0, 0})));  // a point outside
  EXPECT_TRUE(test_obb_obb(kUnit, box({0, 0, 0}, {5, 0, 0})));     // a segment through
  // Two parallel segments half a unit apart, and two equal points.
  EXPECT_FALSE(test_obb_obb(box({0, 0, 0}, {1, 0, 0}), box({0, 0.5, 0}, {1, 0, 0})));
  EXPECT_TRUE(test_obb_obb(box({0, 0, 0}, {0, 0, 0}), box({0, 0, 0}, {0, 0, 0})));
  // A rectangle lying on a face.
  EXPECT_TRUE(test_obb_obb(kUnit, box({0.5, 0.5, 1}, {1, 1, 0}, about_z(0.3))));
}

TEST(TestObbObb, MirrorImageFramesAreBoxesToo) {
  // Found by the campaign: a frame with det = -1 made the two frames' edge-axis projections
  // opposite in sign, and their average zero. The boxes are apart along a_y x b_y.
  const Obb a = box({0, 2.2250738585072009e-308, 1.474329665687315}, {0.010291355337037228, 4, 0},
                    Mat3::from_columns({0, 1, 0}, {0, 0, 1}, {-1, 0, 0}));
  const Obb b = box({0, 6.1041967856476571, 1.474329665687315}, {0, 6.25, 0.02495977756336613},
                    Mat3::from_columns({-0.48031631133764474, -0.069190974004919706, -0.8743619674821459},
                                       {0.22139731982352373, -0.97416636864485051, -0.044532156654100929},
                                       {-0.84869279944981213, -0.21497091737617802, 0.48322669301735111}));
  EXPECT_FALSE(test_obb_obb(a, b));
  EXPECT_FALSE(test_obb_obb(b, a));
}

TEST(TestObbObb, NearlyParallelEdgesNeitherSeparateFalselyNorHideASeparation) {
  const Mat3 tilt = about_z(1e-15);
  EXPECT_TRUE(test_obb_obb(kUnit, box({1.5, 1.5, 0}, {1, 1, 1}, tilt)));
  EXPECT_TRUE(test_obb_obb(box({0, 0, 0}, {100, 0.001, 0.001}), box({0, 0.0015, 0}, {100, 0.001, 0.001}, tilt)));
  EXPECT_FALSE(test_obb_obb(kUnit, box({2.5, 0, 0}, {1, 1, 1}, tilt)));
}

TEST(TestObbObb, IsSymmetricBitForBit) {
  const Obb a = box({0.1, 0.2, 0.3}, {0.5, 0.25, 1}, about_z(0.7));
  const Obb b = box({1.3, 0.9, 0.35}, {0.5, 0.5, 0.5}, about_z(-0.2));
  EXPECT_EQ(test_obb_obb(a, b), test_obb_obb(b, a));
}

// Random pairs, each also moved along the line of centres to either side of the test's own
// first contact (adjacent doubles of the offset's scale), where any difference in the rounding
// would show: every kernel this processor runs answers as the scalar one, and as with the boxes
// swapped.
TEST(TestObbObb, EveryKernelAnswersAlikeAtItsOwnBoundary) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(-1, 1), h(0.05, 0.6);
  const auto rotation = [&] {
    const double a = u(rng), b = u(rng), c = u(rng), d = u(rng), n = std::sqrt(a * a + b * b + c * c + d * d);
    const double w = a / n, x = b / n, y = c / n, z = d / n;
    return Mat3::from_columns({1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
                              {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
                              {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)});
  };
  const auto scalar = [](const Obb& a, const Obb& b) {
    const simd::ForcedKernel forced(simd::Kernel::scalar);
    return test_obb_obb(a, b);
  };
  int hits = 0, pairs = 0;
  for (int round = 0; round < 300; ++round) {
    const Obb a = box({u(rng), u(rng), u(rng)}, {h(rng), h(rng), h(rng)}, rotation());
    const Obb start = box({u(rng), u(rng), u(rng)}, {h(rng), h(rng), h(rng)}, rotation());
    const Vec3 d = start.center - a.center;
    const auto at = [&](double s) { return box(a.center + s * d, start.half, start.axes); };
    double lo = 0, hi = 4;  // the centres together overlap; 4 times the offset apart, not
    for (int k = 0; k < 200 && std::nextafter(lo, hi) != hi; ++k) (scalar(a, at((lo + hi) / 2)) ? lo : hi) = (lo + hi) / 2;
    for (const Obb& b : {start, at(lo), at(hi)}) {
      const bool expected = scalar(a, b);
      hits += expected, ++pairs;
      for (simd::Kernel kernel : simd::supported_kernels()) {
        const simd::ForcedKernel forced(kernel);
        EXPECT_EQ(test_obb_obb(a, b), expected) << to_string(kernel) << ", round " << round;
        EXPECT_EQ(test_obb_obb(b, a), expected) << to_string(kernel) << ", swapped, round " << round;
      }
    }
  }
  EXPECT_GT(hits, pairs / 3);  // both answers are common
  EXPECT_LT(hits, 2 * pairs / 3 + 1);
}

TEST(TestObbObb, OutOfContractInputsGiveNoContact) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(test_obb_obb(kUnit, box({nan, 0, 0}, {1, 1, 1})));
  EXPECT_FALSE(test_obb_obb(kUnit, box({0, 0, 0}, {1, 1, 1}, Mat3::from_columns({1, 0, 0}, {0, nan, 0}, {0, 0, 1}))));
  EXPECT_FALSE(test_obb_obb(kUnit, box({0, 0, 0}, {-1, 1, 1})));
  EXPECT_FALSE(test_obb_obb(kUnit, box({INFINITY, 0, 0}, {1, 1, 1})));
}

TEST(InDomain, EveryNonFiniteEntryAndEveryNegativeHalfExtentIsOutside) {
  EXPECT_TRUE(in_domain(kUnit));
  EXPECT_TRUE(in_domain(box({0, 0, 0}, {0, -0.0, 0})));  // a point; -0 is not negative
  EXPECT_TRUE(in_domain(box({1e300, -1e300, 0}, {1e300, 1e300, 1e300})));
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), double{INFINITY}, -double{INFINITY}}) {
    for (int k = 0; k < 15; ++k) {  // centre, half extents, then the axes column by column
      Obb b = kUnit;
      Vec3& v = k < 3 ? b.center : k < 6 ? b.half : b.axes.col[(k - 6) / 3];
      v = {k % 3 == 0 ? bad : v.x, k % 3 == 1 ? bad : v.y, k % 3 == 2 ? bad : v.z};
      EXPECT_FALSE(in_domain(b)) << "entry " << k << " = " << bad;
    }
  }
  for (int k = 0; k < 3; ++k) {
    Obb b = kUnit;
    b.half = {k == 0 ? -0x1p-1074 : 1, k == 1 ? -0x1p-1074 : 1, k == 2 ? -0x1p-1074 : 1};
    EXPECT_FALSE(in_domain(b)) << "half extent " << k;
  }
}

}  // namespace
}  // namespace cc
