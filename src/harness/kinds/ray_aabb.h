// ray_aabb: a ray (or segment) against an axis-aligned box, intersect_ray_aabb.
#pragma once

#include "harness/formats/parts.h"

namespace cc::harness {

struct RayAabbInput {
  Ray ray;
  Aabb box;
  friend bool operator==(const RayAabbInput&, const RayAabbInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<RayAabbInput> {
  static constexpr auto list = std::tuple{field<&RayAabbInput::ray>(""), field<&RayAabbInput::box>("box")};
};

}  // namespace cc::harness
