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

}  // namespace cc
