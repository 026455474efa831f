// The input of ray_aabb and its fields; the kind's unit is src/harness/kinds/ray_aabb.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct RayAabbInput {
  Ray ray;
  Aabb box;
  friend bool operator==(const RayAabbInput&, const RayAabbInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record: origin, dir, tmin, tmax, box.
template <>
struct Fields<RayAabbInput> {
  static constexpr auto list = std::tuple{field<&RayAabbInput::ray>(""), field<&RayAabbInput::box>("box")};
};

}  // namespace cc::harness
