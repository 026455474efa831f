#include "harness/judging/hull_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace cc::harness {
namespace {

double length2(const Vec3& v) { return v.x * v.x + v.y * v.y + v.z * v.z; }

double distance2_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a, w = p - a;
  const double ee = length2(e);
  const double s = ee > 0 ? std::clamp((w.x * e.x + w.y * e.y + w.z * e.z) / ee, 0.0, 1.0) : 0.0;
  return length2(w - s * e);
}

// The nearest of the edges, or the plane when p's projection falls inside the triangle.
double distance2_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  double best = std::min({distance2_to_segment(p, a, b), distance2_to_segment(p, b, c), distance2_to_segment(p, c, a)});
  const Vec3 n = cross(b - a, c - a);
  const double nn = length2(n);
  if (nn > 0) {
    const auto side = [&](const Vec3& u, const Vec3& v) { const Vec3 k = cross(v - u, p - u); return k.x * n.x + k.y * n.y + k.z * n.z; };
    if (side(a, b) >= 0 && side(b, c) >= 0 && side(c, a) >= 0) {
      const Vec3 w = p - a;
      const double h = w.x * n.x + w.y * n.y + w.z * n.z;
      best = std::min(best, h * h / nn);
    }
  }
  return best;
}

}  // namespace

double distance_to_hull(const Vec3& p, std::span<const Vec3> points) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i; j < n; ++j) {
      for (std::size_t k = j; k < n; ++k) best = std::min(best, distance2_to_triangle(p, points[i], points[j], points[k]));
    }
  }
  return std::sqrt(best);
}

double hull_distance(std::span<const Vec3> a, std::span<const Vec3> b) {
  if (a.empty() != b.empty()) return std::numeric_limits<double>::infinity();
  // Measured on copies scaled to a largest magnitude of about 1, where squares neither underflow
  // nor overflow.
  double m = 0;
  for (std::span<const Vec3> s : {a, b}) {
    for (const Vec3& p : s) m = std::max(m, max_abs(p));
  }
  if (m == 0 || !std::isfinite(m)) return m == 0 ? 0 : std::numeric_limits<double>::infinity();
  const int e = std::ilogb(m);
  const auto scaled = [e](std::span<const Vec3> s) {
    std::vector<Vec3> out;
    for (const Vec3& p : s) out.push_back({std::ldexp(p.x, -e), std::ldexp(p.y, -e), std::ldexp(p.z, -e)});
    return out;
  };
  const std::vector<Vec3> sa = scaled(a), sb = scaled(b);
  double d = 0;
  for (const Vec3& p : sa) d = std::max(d, distance_to_hull(p, sb));
  for (const Vec3& p : sb) d = std::max(d, distance_to_hull(p, sa));
  return std::ldexp(d, e);
}

}  // namespace cc::harness
