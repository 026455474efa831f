// The input of sphere_sphere_distance and its fields; the kind's unit is
// src/harness/kinds/sphere_sphere_distance.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct SphereSphereDistanceInput {
  Sphere a, b;
  friend bool operator==(const SphereSphereDistanceInput&, const SphereSphereDistanceInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<SphereSphereDistanceInput> {
  static constexpr auto list =
      std::tuple{field<&SphereSphereDistanceInput::a>("a"), field<&SphereSphereDistanceInput::b>("b")};
};

/// The answer: hit when the balls meet (signed distance <= 0), and as params the signed distance,
/// a point of a's sphere and one of b's (x, y, z of each), then, from the library, its distance and
/// point error.

}  // namespace cc::harness
