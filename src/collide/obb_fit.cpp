#include "collide/obb_fit.h"

#include <Eigen/Eigenvalues>
#include <vector>


namespace cc {
namespace {

using Matrix = Eigen::Matrix3d;

// The symmetric 3x3 matrix with entries xx, yy, zz, xy, yz, zx.
using Symmetric = std::array<double, 6>;

// x . y summed in order. The axes are a fitting heuristic and the pad covers the projections'
// rounding in any order, so neither needs fp::sum3's symmetry in the coordinates (the
// projections and the areas are most of the fit's arithmetic).
double in_order(const Vec3& x, const Vec3& y) { return x.x * y.x + x.y * y.y + x.z * y.z; }

void add_outer(Symmetric& m, double w, const Vec3& v) {
  m[0] += w * v.x * v.x, m[1] += w * v.y * v.y, m[2] += w * v.z * v.z;
  m[3] += w * v.x * v.y, m[4] += w * v.y * v.z, m[5] += w * v.z * v.x;
}

// The covariance of the hull's surface (each triangle weighted by its area: the sum of
// area/12 (S S^T + p p^T + q q^T + r r^T), S = p + q + r, over the area, minus the mean's outer
// product); coordinates relative to `origin`. The vertex terms are gathered per vertex (each
// weighted by the area of the triangles around it), one outer product per vertex instead of one
// per corner. With no area, the points' own covariance (a segment's direction, or nothing for one
// point).
Symmetric covariance(std::span<const Vec3> points, const ConvexHull& hull, const Vec3& origin) {
  thread_local std::vector<double> weight;  // per point: the area of its triangles
  weight.assign(points.size(), 0);
  Symmetric second{};
  Vec3 centroid{0, 0, 0};
  double area = 0;
  for (const auto& t : hull.triangles) {
    const Vec3 p = points[t[0]] - origin, q = points[t[1]] - origin, r = points[t[2]] - origin;
    const Vec3 n = cross(q - p, r - p);
    const double a = 0.5 * std::sqrt(in_order(n, n));
    const Vec3 sum = p + q + r;
    add_outer(second, a / 12, sum);
    for (std::uint32_t v : t) weight[v] += a;
    centroid = centroid + (a / 3) * sum;
    area += a;
  }
  Symmetric c{};
  if (area > 0) {
    for (std::size_t v = 0; v < points.size(); ++v) {
      if (weight[v] > 0) add_outer(second, weight[v] / 12, points[v] - origin);
    }
    const Vec3 mean = (1 / area) * centroid;
    for (int i = 0; i < 6; ++i) c[i] = second[i] / area;
    add_outer(c, -1, mean);
    return c;
  }
  Vec3 mean{0, 0, 0};
  for (const Vec3& p : points) mean = mean + (p - origin);
  mean = (1 / static_cast<double>(points.size())) * mean;
  for (const Vec3& p : points) add_outer(c, 1, (p - origin) - mean);
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
  Eigen::SelfAdjointEigenSolver<Matrix> solver;
  solver.computeDirect(cov);
  const Matrix& v = solver.eigenvectors();  // columns, by increasing eigenvalue
  const Vec3 major{v(0, 2), v(1, 2), v(2, 2)}, middle{v(0, 1), v(1, 1), v(2, 1)};
  if (solver.info() != Eigen::Success || !finite(major) || !finite(middle)) return Mat3::identity();
  const Vec3 a0 = normalized(major);
  const Vec3 a1 = normalized(middle - dot(middle, a0) * a0);
  return Mat3::from_columns(a0, a1, cross(a0, a1));
}

Mat3 obb_axes(std::span<const Vec3> points, const ConvexHull& hull) {
  return principal_axes(covariance(points, hull, points[0]));
}

std::optional<Mat3> triangle_axes(const Vec3& p, const Vec3& q, const Vec3& r) {
  const Vec3 n = cross(q - p, r - p);
  const double longest = std::max({dot(q - p, q - p), dot(r - q, r - q), dot(p - r, p - r)});
  if (!(dot(n, n) > 0x1p-40 * longest * longest)) return std::nullopt;
  // An orthonormal frame of the plane, and the vertices' 2x2 covariance about the centroid in it.
  const Vec3 u = normalized(q - p), v = normalized(cross(n, u));
  const Vec3 c = (1.0 / 3) * (p + q + r);
  double xx = 0, xy = 0, yy = 0;
  for (const Vec3& w : {p, q, r}) {
    const double x = in_order(w - c, u), y = in_order(w - c, v);
    xx += x * x, xy += x * y, yy += y * y;
  }
  // The eigenvector of the larger eigenvalue l: (l - yy, xy) or (xy, l - xx), whichever is longer.
  const double half_gap = 0.5 * (xx - yy);
  const double l = 0.5 * (xx + yy) + std::sqrt(half_gap * half_gap + xy * xy);
  double a = l - yy, b = xy;
  if (std::fabs(l - xx) > std::fabs(a)) a = xy, b = l - xx;
  if (a == 0 && b == 0) a = 1;  // isotropic: any direction in the plane
  const Vec3 major = normalized(a * u + b * v), middle = -b * u + a * v;
  const Vec3 a0 = major, a1 = normalized(middle - dot(middle, a0) * a0);
  return Mat3::from_columns(a0, a1, cross(a0, a1));
}

Obb fit_obb(std::span<const Vec3> points) {
  if (points.size() == 3) {
    if (const std::optional<Mat3> axes = triangle_axes(points[0], points[1], points[2])) return fit_obb(*axes, points);
  }
  thread_local ConvexHull hull;
  fast_convex_hull(points, hull);
  return fit_obb(obb_axes(points, hull), points);
}

Obb fit_obb(const Mat3& axes, std::span<const Vec3> points) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY}, largest{0, 0, 0};
  for (const Vec3& p : points) {
    const Vec3 s{in_order(axes.col[0], p), in_order(axes.col[1], p), in_order(axes.col[2], p)};
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], s[i]), hi[i] = std::max(hi[i], s[i]);
      largest[i] = std::max(largest[i], std::fabs(p[i]));
    }
  }
  const double magnitude = norm1(largest);  // at least every point's norm1
  Obb box;
  box.axes = axes;
  const Vec3 mid = 0.5 * (lo + hi);
  box.center = axes * mid;
  const Vec3 half = 0.5 * (hi - lo);
  const double pad = 0x1p-44 * (magnitude + norm1(mid) + norm1(half)) + fp::subnormal_slack;
  box.half = {half.x + pad, half.y + pad, half.z + pad};
  return box;
}

Obb merge_obbs(const Obb& a, const Obb& b, const Mat3& axes) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  double magnitude = 0;
  for (const Obb* box : {&a, &b}) {
    for (int i = 0; i < 3; ++i) {
      const Vec3& u = axes.col[i];
      const double c = in_order(u, box->center);
      const double r = std::fabs(in_order(u, box->axes.col[0])) * box->half.x +
                       std::fabs(in_order(u, box->axes.col[1])) * box->half.y +
                       std::fabs(in_order(u, box->axes.col[2])) * box->half.z;
      lo[i] = std::min(lo[i], c - r), hi[i] = std::max(hi[i], c + r);
    }
    const Vec3 reach = box->half.x * abs(box->axes.col[0]) + box->half.y * abs(box->axes.col[1]) +
                       box->half.z * abs(box->axes.col[2]);
    magnitude = std::max(magnitude, in_order(abs(box->center) + reach, {1, 1, 1}));
  }
  Obb m;
  m.axes = axes;
  const Vec3 mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  m.center = axes * mid;
  const double pad = 0x1p-44 * (magnitude + norm1(mid) + norm1(half)) + fp::subnormal_slack;
  m.half = {half.x + pad, half.y + pad, half.z + pad};
  return m;
}

}  // namespace cc
