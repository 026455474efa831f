// The bound of intersect_ray_aabb's slab parameters (widening.h), which test_ray_aabbs and
// ray_mesh's box entries share.
#pragma once

#include "collide/aabb.h"
#include "collide/ray.h"
#include "collide/record_sink.h"
#include "collide/widening.h"

namespace cc::bounds {

/// A slab parameter (bound - origin) * (1 / dir) carries three roundings, at most 3.000001u
/// relative; 8u also covers the rounding of the widened value itself.
inline constexpr Widening kRaySlab{"slab parameter", 8 * fp::u};

}  // namespace cc::bounds

namespace cc {

struct RayHit;  // ray_aabb.h, which includes this header for kRaySlab

/// The same as its plain version (ray_aabb.h), recording its certified quantities into `records`
/// (bound_records.h); the same answer, bit for bit.
RayHit intersect_ray_aabb(const Ray& ray, const Aabb& box, bounds::Records& records);

}  // namespace cc
