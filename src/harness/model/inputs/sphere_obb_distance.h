// The input of sphere_obb_distance and its fields; the kind's unit is
// src/harness/kinds/sphere_obb_distance.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct SphereObbDistanceInput {
  Sphere ball;
  Obb box;
  friend bool operator==(const SphereObbDistanceInput&, const SphereObbDistanceInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<SphereObbDistanceInput> {
  static constexpr auto list =
      std::tuple{field<&SphereObbDistanceInput::ball>("ball"), field<&SphereObbDistanceInput::box>("box")};
};

/// The answer: hit when the ball and the box meet (signed distance <= 0), and as params the signed
/// distance, a point of the ball's sphere and one of the box's boundary (x, y, z of each), then,
/// from the library, its distance and point error.

}  // namespace cc::harness
