#include "collide/object_bounds.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "collide/cube_bound.h"
#include "collide/record_sink.h"
#include "collide/sphere_fit.h"

namespace cc {
namespace {

// |v| as computed, and that length padded up (bounds::padded_radius, and one step more when the
// scaling back rounds). v is scaled by a power of two first, so that its squares neither underflow (a
// subnormal vertex) nor overflow; components 2^1074 below the largest, lost by the scaling,
// change the length by far less than the padding.
bounds::RadiusRoot length(const Vec3& v) {
  const double m = max_abs(v);
  if (!(m > 0) || !std::isfinite(m)) return {v, m, m};
  const int e = std::ilogb(m);
  const Vec3 w{std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)};
  const double root = std::sqrt(dot(w, w));
  double padded = std::ldexp(bounds::padded_radius(root), e);
  if (padded < DBL_MIN) padded = std::nextafter(padded, INFINITY);  // ldexp rounded a subnormal
  return {v, std::ldexp(root, e), padded};
}

template <class Records>
double radius(const Mesh& mesh, Records& records) {
  double r = 0;
  for (const Vec3& v : mesh.vertices) {
    const bounds::RadiusRoot root = length(v);
    records.add(root);
    r = std::max(r, root.padded);
  }
  return r;
}

template <class Records>
Aabb cube(double radius, const RigidTransform& pose, Records& records) {
  const bounds::CubeBound bound{radius, {3 * radius, max_abs(pose.translation)}};
  const double pad = bound.half_side();
  const Vec3 half{pad, pad, pad};
  Aabb box{pose.translation - half, pose.translation + half};
  for (int k = 0; k < 3; ++k) {  // the sums above round to nearest: step outward
    box.lo[k] = std::nextafter(box.lo[k], -INFINITY);
    box.hi[k] = std::nextafter(box.hi[k], INFINITY);
  }
  records.add(bounds::Cube{pose, bound, box});
  return box;
}

template <class Records>
Aabb fitted(const Mesh& mesh, const RigidTransform& pose, Records& records) {
  if (mesh.vertices.empty()) return {pose.translation, pose.translation};
  Aabb box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  double reach = 0;
  for (const Vec3& v : mesh.vertices) {
    const Vec3 p = apply(pose, v);
    reach = std::max(reach, norm1(v));
    for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], p[k]), box.hi[k] = std::max(box.hi[k], p[k]);
  }
  const bounds::TransformBound transform{reach, max_abs(pose.translation)};
  if constexpr (!std::is_same_v<Records, bounds::NoRecords>) {  // each placement, as apply() computes it
    for (const Vec3& v : mesh.vertices) {
      const Vec3 rotated = pose.rotation * v;
      records.add(bounds::Placement{pose, v, rotated, rotated + pose.translation, transform});
    }
  }
  const double pad = transform.total() * (1 + 0x1p-50);
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = std::nextafter(box.lo[k] - pad, -INFINITY);
    box.hi[k] = std::nextafter(box.hi[k] + pad, INFINITY);
  }
  return box;
}

}  // namespace

double rotation_radius(const Mesh& mesh) {
  bounds::NoRecords none;
  return radius(mesh, none);
}

double rotation_radius(const Mesh& mesh, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return radius(mesh, into);
}

Aabb bounding_cube(double radius, const RigidTransform& pose) {
  bounds::NoRecords none;
  return cube(radius, pose, none);
}

Aabb bounding_cube(double radius, const RigidTransform& pose, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return cube(radius, pose, into);
}

Sphere mesh_ball(const Mesh& mesh) { return mesh.vertices.empty() ? Sphere{} : fit_sphere(mesh.vertices); }

// A point p of the ball (|p - c| <= r) is placed at R p + T exactly and at apply(pose, p) within
// transform_error_bound per coordinate (sqrt(3) times it in length); the centre at apply(pose, c)
// likewise. |R (p - c)| <= (1 + 2^-47) r for R orthonormal within 2^-48, so both placements of p
// lie within (1 + 2^-47) r + 2 sqrt(3) e of the placed centre, e = transform_error_bound for
// points of norm1 up to |c|_1 + sqrt(3) r. The radius r + 2^-40 r + 4 e covers that and its own
// rounding (each sum rounds by at most u of it: one step up more).
Sphere placed_ball(const Sphere& ball, const RigidTransform& pose) {
  const double e = transform_error_bound(pose, norm1(ball.center) + 2 * ball.radius);
  const double radius = (ball.radius + ball.radius * 0x1p-40) + 4 * e;
  return {apply(pose, ball.center), std::nextafter(radius, INFINITY)};
}

Aabb box_of(const Sphere& ball) {
  Aabb box;
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = std::nextafter(ball.center[k] - ball.radius, -INFINITY);
    box.hi[k] = std::nextafter(ball.center[k] + ball.radius, INFINITY);
  }
  return box;
}

Aabb fitted_box(const Mesh& mesh, const RigidTransform& pose) {
  bounds::NoRecords none;
  return fitted(mesh, pose, none);
}

Aabb fitted_box(const Mesh& mesh, const RigidTransform& pose, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return fitted(mesh, pose, into);
}

}  // namespace cc
