// The input of tri_obb_distance and its fields; the kind's unit is
// src/harness/kinds/tri_obb_distance.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct TriObbDistanceInput {
  Triangle tri;
  Obb box;
  friend bool operator==(const TriObbDistanceInput&, const TriObbDistanceInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<TriObbDistanceInput> {
  static constexpr auto list =
      std::tuple{field<&TriObbDistanceInput::tri>("triangle"), field<&TriObbDistanceInput::box>("box")};
};

/// The answer: hit when the triangle and the box meet (signed distance <= 0), and as params the
/// signed distance, a point of the triangle and one of the box (x, y, z of each), then, from the
/// library, its distance and point error.

}  // namespace cc::harness
