// Rays and segments against axis-aligned boxes, by slabs.
#pragma once

#include "collide/aabb.h"

namespace cc {

/// The points origin + t * dir for t in [tmin, tmax]. tmax may be +inf (a ray) and tmin may be
/// -inf; a finite tmax makes a segment. dir need not be normalised; dir = 0 is a point.
struct Ray {
  Vec3 origin;
  Vec3 dir;
  double tmin = 0;
  double tmax = INFINITY;
  friend constexpr bool operator==(const Ray&, const Ray&) = default;
};

/// Where a ray meets a box: the parameter interval [t_enter, t_exit] of the ray inside it.
struct RayHit {
  bool hit = false;
  double t_enter = 0;
  double t_exit = 0;
};

/// Intersects a ray with a closed box by the slab method. On a hit, t_enter and t_exit bound
/// the part of [tmin, tmax] inside the box, each within 4 ulps of its exact value.
///  - Parallel: a direction component that is 0, -0, or so small (subnormal) that its
///    reciprocal overflows makes the ray parallel to that slab; it then meets the slab only if
///    the origin lies in the closed slab, and that decision is exact.
///  - Conservative: a ray that touches the box in exact arithmetic (grazing a face, an edge or
///    a corner; t_enter == t_exit) is always a hit; a ray that misses by less than 2^-46 of
///    the largest coordinate may be reported as a hit. For such a grazing hit t_enter may
///    exceed t_exit by the rounding above.
///  - tmax = 0 with tmin = 0 tests the origin alone. A ray starting inside has t_enter = tmin.
///  - Domain: finite coordinates, and every slab parameter (bound - origin) / dir within 2^1000
///    in magnitude. NaN anywhere, an infinite coordinate, tmin = +inf, tmax = -inf, or an
///    inverted box (lo > hi) give no hit.
RayHit intersect_ray_aabb(const Ray& ray, const Aabb& box);

/// A ray made ready to meet many boxes: the scaling of its direction, the reciprocals and the
/// checks that concern the ray alone, done once (the fields are read by the batched test).
/// intersect_ray_aabb(PreparedRay(ray), box) returns what intersect_ray_aabb(ray, box)
/// returns, bit for bit, in and out of the contract.
struct PreparedRay {
  explicit PreparedRay(const Ray& ray);

  Ray ray;                    // as given
  bool in_contract = false;   // the ray's half of the contract, and tmin <= tmax
  int exponent = 0;           // the direction is scaled by 2^-exponent
  double tmin = 0, tmax = 0;  // scaled
  int parallel = 0;           // bit i: |dir[i]| <= 2^-1024, the origin decides
  int subnormal = 0;          // bit i: scaled, dir[i] is subnormal (its slab in long double)
  bool negative[3] = {false, false, false};  // dir[i] < 0: the slab's near bound is its upper one
  double inv_scaled[3] = {0, 0, 0};          // 1 / scaled dir[i]
};

/// The same answer as intersect_ray_aabb(ray.ray, box), with the ray's work done once.
RayHit intersect_ray_aabb(const PreparedRay& ray, const Aabb& box);

}  // namespace cc
