#include "collide/obb_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

// The closed form for one triangle gives obb_axes's axes (through the hull, Eigen's 3x3 solver)
// up to sign, when the in-plane variances differ; right-handed and orthonormal; nothing for
// slivers, collinear and repeated vertices.
TEST(TriangleAxes, AreTheHullCovariancesAxes) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> uniform(-1, 1);
  int compared = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const double scale = std::ldexp(1.0, static_cast<int>(trial % 61) - 30);
    const Vec3 offset{std::ldexp(uniform(random), trial % 40), uniform(random), 0};
    std::vector<Vec3> t;
    for (int k = 0; k < 3; ++k) t.push_back(offset + scale * Vec3{uniform(random), uniform(random), uniform(random)});
    const std::optional<Mat3> axes = triangle_axes(t[0], t[1], t[2]);
    ASSERT_TRUE(axes.has_value()) << "trial " << trial;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) ASSERT_NEAR(dot(axes->col[i], axes->col[j]), i == j ? 1 : 0, 0x1p-50);
    }
    ASSERT_GT(dot(cross(axes->col[0], axes->col[1]), axes->col[2]), 0);
    // The in-plane variances along the axes; compare directions where they differ clearly.
    const Vec3 c = (1.0 / 3) * (t[0] + t[1] + t[2]);
    double v0 = 0, v1 = 0;
    for (const Vec3& p : t) v0 += dot(p - c, axes->col[0]) * dot(p - c, axes->col[0]), v1 += dot(p - c, axes->col[1]) * dot(p - c, axes->col[1]);
    ASSERT_GE(v0, v1 * (1 - 1e-9)) << "trial " << trial;
    if (v0 < 1.01 * v1 || std::fabs(offset.x) > 1e3 * scale) continue;
    const Mat3 expected = obb_axes(t, convex_hull(t));
    for (int i = 0; i < 3; ++i) ASSERT_NEAR(std::fabs(dot(axes->col[i], expected.col[i])), 1, 1e-6) << "trial " << trial;
    ++compared;
  }
  EXPECT_GT(compared, 500);
  EXPECT_FALSE(triangle_axes({0, 0, 0}, {1, 1, 1}, {3, 3, 3}).has_value());  // collinear
  EXPECT_FALSE(triangle_axes({0, 0, 0}, {0, 0, 0}, {1, 0, 0}).has_value());  // a repeated vertex
  EXPECT_FALSE(triangle_axes({0, 0, 0}, {1, 0, 0}, {0.5, 0x1p-30, 0}).has_value());  // a sliver
  const std::optional<Mat3> flat = triangle_axes({0, 0, 1}, {4, 0, 1}, {0, 3, 1});
  ASSERT_TRUE(flat.has_value());
  EXPECT_NEAR(std::fabs(flat->col[2].z), 1, 1e-15);  // the normal last
}

}  // namespace
}  // namespace cc
