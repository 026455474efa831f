#include "collide/object_bounds.h"

#include <algorithm>
#include <cmath>

namespace cc {

namespace {

// |v| rounded up. v is scaled by a power of two first, so that its squares neither underflow
// (a subnormal vertex) nor overflow; components 2^1074 below the largest, lost by the scaling,
// change the length by far less than the padding.
double length_up(const Vec3& v) {
  const double m = max_abs(v);
  if (!(m > 0) || !std::isfinite(m)) return m;
  const int e = std::ilogb(m);
  const Vec3 w{std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)};
  // dot and sqrt round by less than 2^-51 in all; ldexp may round once more (subnormal result).
  return std::nextafter(std::ldexp(std::sqrt(dot(w, w)) * (1 + 0x1p-50), e), INFINITY);
}

}  // namespace

double rotation_radius(const Mesh& mesh) {
  double r = 0;
  for (const Vec3& v : mesh.vertices) r = std::max(r, length_up(v));
  return r;
}

Aabb bounding_cube(double radius, const RigidTransform& pose) {
  const double pad = radius * (1 + 0x1p-40) + transform_error_bound(pose, 3 * radius);
  const Vec3 half{pad, pad, pad};
  Aabb box{pose.translation - half, pose.translation + half};
  for (int k = 0; k < 3; ++k) {  // the sums above round to nearest: step outward
    box.lo[k] = std::nextafter(box.lo[k], -INFINITY);
    box.hi[k] = std::nextafter(box.hi[k], INFINITY);
  }
  return box;
}

Aabb fitted_box(const Mesh& mesh, const RigidTransform& pose) {
  if (mesh.vertices.empty()) return {pose.translation, pose.translation};
  Aabb box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  double reach = 0;
  for (const Vec3& v : mesh.vertices) {
    const Vec3 p = apply(pose, v);
    reach = std::max(reach, norm1(v));
    for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], p[k]), box.hi[k] = std::max(box.hi[k], p[k]);
  }
  const double pad = transform_error_bound(pose, reach) * (1 + 0x1p-50);
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = std::nextafter(box.lo[k] - pad, -INFINITY);
    box.hi[k] = std::nextafter(box.hi[k] + pad, INFINITY);
  }
  return box;
}

}  // namespace cc
