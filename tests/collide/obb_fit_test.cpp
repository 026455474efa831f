#include "collide/obb_fit.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cc {
namespace {

// The point's coordinates along the box's axes, relative to its centre.
Vec3 local(const Obb& b, const Vec3& p) { return transpose_times(b.axes, p - b.center); }

bool contains(const Obb& b, const Vec3& p) {
  const Vec3 u = local(b, p);
  return std::fabs(u.x) <= b.half.x && std::fabs(u.y) <= b.half.y && std::fabs(u.z) <= b.half.z;
}

Mat3 rotation(double a, double b) {
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
  const Mat3 z = Mat3::from_columns({ca, sa, 0}, {-sa, ca, 0}, {0, 0, 1});
  const Mat3 x = Mat3::from_columns({1, 0, 0}, {0, cb, sb}, {0, -sb, cb});
  Mat3 r;
  for (int c = 0; c < 3; ++c) r.col[c] = z * x.col[c];
  return r;
}

TEST(FitObb, FindsTheFrameOfARotatedBox) {
  const Mat3 r = rotation(0.4, 1.1);
  std::vector<Vec3> points;
  for (int i = 0; i < 8; ++i) {
    const Vec3 u{(i & 1) ? 5.0 : -5.0, (i & 2) ? 2.0 : -2.0, (i & 4) ? 0.5 : -0.5};
    points.push_back(r * u + Vec3{10, -3, 7});
  }
  const Obb b = fit_obb(points);
  for (const Vec3& p : points) EXPECT_TRUE(contains(b, p));
  EXPECT_NEAR(std::fabs(dot(b.axes.col[0], r.col[0])), 1, 1e-12);  // the longest axis first
  EXPECT_NEAR(b.half.x, 5, 1e-9);
  EXPECT_NEAR(b.half.y, 2, 1e-9);
  EXPECT_NEAR(b.half.z, 0.5, 1e-9);
  EXPECT_NEAR(b.center.x, 10, 1e-9);
}

TEST(FitObb, AxesAreRightHandedAndOrthonormal) {
  const std::vector<Vec3> points = {{0, 0, 0}, {3, 1, 0}, {1, 4, 2}, {-2, 1, 5}, {0.5, 0.25, -1}};
  const Obb b = fit_obb(points);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(dot(b.axes.col[i], b.axes.col[j]), i == j ? 1 : 0, 0x1p-50);
  }
  EXPECT_GT(dot(cross(b.axes.col[0], b.axes.col[1]), b.axes.col[2]), 0);
  for (const Vec3& p : points) EXPECT_TRUE(contains(b, p));
}

TEST(FitObb, AFlatTriangleGetsItsNormalAsAnAxis) {
  const std::vector<Vec3> tri = {{0, 0, 1}, {4, 0, 1}, {0, 3, 1}};
  const Obb b = fit_obb(tri);
  EXPECT_NEAR(std::fabs(b.axes.col[2].z), 1, 1e-12);  // the smallest extent along z
  EXPECT_LT(b.half.z, 1e-9);
  for (const Vec3& p : tri) EXPECT_TRUE(contains(b, p));
}

TEST(FitObb, SegmentsAndPointsGiveThinBoxes) {
  const std::vector<Vec3> segment = {{1, 1, 1}, {3, 3, 3}, {2, 2, 2}};
  const Obb s = fit_obb(segment);
  EXPECT_NEAR(s.half.x, std::sqrt(3.0), 1e-9);
  EXPECT_LT(s.half.y + s.half.z, 1e-9);
  const std::vector<Vec3> point = {{5, 5, 5}};
  const Obb p = fit_obb(point);
  EXPECT_EQ(p.axes, Mat3::identity());
  EXPECT_LT(p.half.x, 1e-9);
  EXPECT_TRUE(contains(p, point[0]));
}

TEST(FitObb, CornersSpanTheBox) {
  const Obb b{{1, 2, 3}, {1, 2, 3}, Mat3::identity()};
  const auto c = corners(b);
  EXPECT_EQ(c[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(c[7], (Vec3{2, 4, 6}));
}

}  // namespace
}  // namespace cc
