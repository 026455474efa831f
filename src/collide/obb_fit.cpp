#include "collide/obb_fit.h"

#include <Eigen/Eigenvalues>


namespace cc {
namespace {

using Matrix = Eigen::Matrix3d;

Eigen::Vector3d eigen(const Vec3& v) { return {v.x, v.y, v.z}; }

// Sum over the hull's triangles of area/12 (9 m m^T + p p^T + q q^T + r r^T), with m the centroid,
// and the hull's area and area-weighted centroid; coordinates relative to `origin`.
struct SurfaceMoments {
  Matrix second = Matrix::Zero();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double area = 0;
};

SurfaceMoments surface_moments(std::span<const Vec3> points, const ConvexHull& hull, const Vec3& origin) {
  SurfaceMoments s;
  for (const auto& t : hull.triangles) {
    const Eigen::Vector3d p = eigen(points[t[0]] - origin), q = eigen(points[t[1]] - origin),
                          r = eigen(points[t[2]] - origin);
    const double area = 0.5 * (q - p).cross(r - p).norm();
    const Eigen::Vector3d m = (p + q + r) / 3;
    s.second += area / 12 * (9 * m * m.transpose() + p * p.transpose() + q * q.transpose() + r * r.transpose());
    s.centroid += area * m;
    s.area += area;
  }
  return s;
}

Matrix covariance(std::span<const Vec3> points, const ConvexHull& hull, const Vec3& origin) {
  const SurfaceMoments s = surface_moments(points, hull, origin);
  if (s.area > 0) {
    const Eigen::Vector3d mean = s.centroid / s.area;
    return s.second / s.area - mean * mean.transpose();
  }
  // No area: the points' own covariance (a segment's direction, or nothing for one point).
  Matrix c = Matrix::Zero();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Vec3& p : points) mean += eigen(p - origin);
  mean /= static_cast<double>(points.size());
  for (const Vec3& p : points) {
    const Eigen::Vector3d d = eigen(p - origin) - mean;
    c += d * d.transpose();
  }
  return c;
}

Vec3 normalized(const Vec3& v) {
  const double n = std::sqrt(dot(v, v));
  return (1 / n) * v;
}

}  // namespace

// Gram-Schmidt on the eigenvectors of the two largest eigenvalues.
Mat3 principal_axes(const std::array<double, 6>& m) {
  Matrix cov;
  cov << m[0], m[3], m[5], m[3], m[1], m[4], m[5], m[4], m[2];
  if (cov.isZero(0)) return Mat3::identity();  // a single point: any frame, the simplest
  Eigen::SelfAdjointEigenSolver<Matrix> solver(cov);
  const Matrix& v = solver.eigenvectors();  // columns, by increasing eigenvalue
  const Vec3 major{v(0, 2), v(1, 2), v(2, 2)}, middle{v(0, 1), v(1, 1), v(2, 1)};
  if (solver.info() != Eigen::Success || !finite(major) || !finite(middle)) return Mat3::identity();
  const Vec3 a0 = normalized(major);
  const Vec3 a1 = normalized(middle - dot(middle, a0) * a0);
  return Mat3::from_columns(a0, a1, cross(a0, a1));
}

Mat3 obb_axes(std::span<const Vec3> points, const ConvexHull& hull) {
  const Matrix c = covariance(points, hull, points[0]);
  return principal_axes({c(0, 0), c(1, 1), c(2, 2), c(0, 1), c(1, 2), c(2, 0)});
}

Obb fit_obb(std::span<const Vec3> points) { return fit_obb(obb_axes(points, convex_hull(points)), points); }

Obb fit_obb(const Mat3& axes, std::span<const Vec3> points) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  double magnitude = 0;
  for (const Vec3& p : points) {
    const Vec3 s = transpose_times(axes, p);
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], s[i]), hi[i] = std::max(hi[i], s[i]);
    magnitude = std::max(magnitude, norm1(p));
  }
  Obb box;
  box.axes = axes;
  const Vec3 mid = 0.5 * (lo + hi);
  box.center = axes * mid;
  const Vec3 half = 0.5 * (hi - lo);
  const double pad = 0x1p-44 * (magnitude + norm1(mid) + norm1(half)) + fp::subnormal_slack;
  box.half = {half.x + pad, half.y + pad, half.z + pad};
  return box;
}

std::array<Vec3, 8> corners(const Obb& box) {
  std::array<Vec3, 8> out;
  for (int i = 0; i < 8; ++i) {
    const double s0 = (i & 1) ? box.half.x : -box.half.x, s1 = (i & 2) ? box.half.y : -box.half.y,
                 s2 = (i & 4) ? box.half.z : -box.half.z;
    out[i] = box.center + box.axes * Vec3{s0, s1, s2};
  }
  return out;
}

}  // namespace cc
