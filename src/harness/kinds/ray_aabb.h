// ray_aabb: a ray (or segment) against an axis-aligned box, intersect_ray_aabb.
#pragma once

#include "collide/aabb.h"
#include "collide/ray_aabb.h"

namespace cc::harness {

struct RayAabbInput {
  Ray ray;
  Aabb box;
  friend bool operator==(const RayAabbInput&, const RayAabbInput&) = default;
};

}  // namespace cc::harness
