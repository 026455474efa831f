// Rays and segments against axis-aligned boxes, by slabs.
#pragma once

#include <algorithm>
#include <cmath>

#include "collide/aabb.h"
#include "collide/ray.h"
#include "collide/ray_slab_bound.h"

namespace cc {

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
  bool plain = false;         // in contract, no slab subnormal: the common case
};

namespace detail {

/// The whole test on a prepared ray (ray_aabb.cpp).
RayHit intersect_prepared(const PreparedRay& ray, const Aabb& box);

/// The miss decision of intersect_prepared on a plain PreparedRay, alone: the same entry and
/// exit over the slabs, widened and compared, and the origin against the parallel slabs, so that
/// true here is a miss there: a slab's near and far parameters are the same expressions (the
/// bound the direction's sign picks, minus the origin, times the reciprocal) on every box.
template <bool kParallel>
inline bool certainly_missed(const PreparedRay& r, const Aabb& box) {
  double enter = -INFINITY, exit = INFINITY;  // (max and min replace them by any value but NaN)
  for (int i = 0; i < 3; ++i) {
    if (kParallel && ((r.parallel >> i) & 1)) {
      if (r.ray.origin[i] < box.lo[i] || r.ray.origin[i] > box.hi[i]) return true;
      continue;
    }
    const double near = ((r.negative[i] ? box.hi[i] : box.lo[i]) - r.ray.origin[i]) * r.inv_scaled[i];
    const double far = ((r.negative[i] ? box.lo[i] : box.hi[i]) - r.ray.origin[i]) * r.inv_scaled[i];
    enter = kParallel || i > 0 ? std::max(enter, near) : near;
    exit = kParallel || i > 0 ? std::min(exit, far) : far;
  }
  if (r.tmin >= 0) {
    // A widened entry below 0 loses to tmin, and an exit below 0 to the entry, whichever product
    // widened them (or they are too small for the products to differ): the same decision.
    constexpr double a = 1 - bounds::kRaySlab.relative, b = 1 + bounds::kRaySlab.relative;
    return !(std::max(r.tmin, enter * a - fp::subnormal_slack) <= std::min(r.tmax, exit * b + fp::subnormal_slack));
  }
  return !(std::max(r.tmin, bounds::kRaySlab.lower(enter)) <= std::min(r.tmax, bounds::kRaySlab.upper(exit)));
}

}  // namespace detail

/// The same answer as intersect_ray_aabb(ray.ray, box), with the ray's work done once. Inline:
/// a plain ray's misses (most boxes) are decided without a call.
inline RayHit intersect_ray_aabb(const PreparedRay& ray, const Aabb& box) {
  if (ray.plain && (ray.parallel == 0 ? detail::certainly_missed<false>(ray, box) : detail::certainly_missed<true>(ray, box))) {
    return {};
  }
  return detail::intersect_prepared(ray, box);
}

}  // namespace cc
