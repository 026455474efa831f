#include "collide/sphere_fit.h"

#include <cmath>

namespace cc {
namespace {

// x rounded up to the next double: at least any real that rounds to nearest as x.
double next_up(double x) { return std::nextafter(x, INFINITY); }

// |p - q| in floating point, unchecked: for choosing centres only.
double distance(const Vec3& p, const Vec3& q) {
  const Vec3 d = p - q;
  return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

}  // namespace

// d = p - q rounds each coordinate by at most u of itself, so |p - q| <= |d| / (1 - u). Scaled by
// 2^-e so that its largest coordinate lies in [1, 2) (exact, but for coordinates below 2^-1022
// once scaled, off by at most 2^-1075 each, far below the rest), its squares' sum rounds by at
// most 3u and the square root by u: |p - q| <= 2^e sqrt(s) (1 + 5u). The factor 1 + 2^-48 rounds
// to at least 1 + 2^-49 > 1 + 5u; 2^e times it is exact unless it falls below 2^-1022.
double distance_upper_bound(const Vec3& p, const Vec3& q) {
  const Vec3 d = p - q;
  const double m = max_abs(d);
  if (m == 0) return 0;
  const int e = fp::exponent_of(m);
  const Vec3 s{fp::scale2(d.x, -e), fp::scale2(d.y, -e), fp::scale2(d.z, -e)};
  const double root = std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z) * (1 + 0x1p-48);
  return fp::scale2(root, e) + fp::subnormal_slack;
}

Sphere fit_sphere(std::span<const Vec3> points) {
  const auto farthest = [&points](const Vec3& from) {
    const Vec3* best = &points[0];
    double best_d2 = -1;
    for (const Vec3& p : points) {
      const Vec3 d = p - from;
      const double d2 = d.x * d.x + d.y * d.y + d.z * d.z;
      if (d2 > best_d2) best_d2 = d2, best = &p;
    }
    return *best;
  };
  const Vec3 y = farthest(points[0]);
  const Vec3 z = farthest(y);
  Vec3 center = 0.5 * (y + z);
  double radius = 0.5 * distance(y, z);
  for (const Vec3& p : points) {
    const double d = distance(p, center);
    if (!(d > radius)) continue;
    const double grown = 0.5 * (radius + d);
    center = center + ((grown - radius) / d) * (p - center);
    radius = grown;
  }
  // The centre is a heuristic; the radius holds every point from it.
  double certified = 0;
  for (const Vec3& p : points) certified = std::max(certified, distance_upper_bound(p, center));
  return {center, certified};
}

Sphere merge_spheres(const Sphere& a, const Sphere& b) {
  const double d = distance_upper_bound(a.center, b.center);
  if (d == 0) return a.radius >= b.radius ? a : b;  // the same centre: the larger ball
  if (next_up(d + b.radius) <= a.radius) return a;
  if (next_up(d + a.radius) <= b.radius) return b;
  const double radius = 0.5 * (d + a.radius + b.radius);
  const Vec3 center = a.center + ((radius - a.radius) / d) * (b.center - a.center);
  return {center, std::max(next_up(distance_upper_bound(center, a.center) + a.radius),
                           next_up(distance_upper_bound(center, b.center) + b.radius))};
}

}  // namespace cc
