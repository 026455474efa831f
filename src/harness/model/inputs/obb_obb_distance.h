// The input of obb_obb_distance and its fields; the kind's unit is
// src/harness/kinds/obb_obb_distance.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct ObbObbDistanceInput {
  Obb a, b;
  friend bool operator==(const ObbObbDistanceInput&, const ObbObbDistanceInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<ObbObbDistanceInput> {
  static constexpr auto list = std::tuple{field<&ObbObbDistanceInput::a>("a"), field<&ObbObbDistanceInput::b>("b")};
};

/// The answer: hit when the boxes meet (signed distance <= 0), and as params the signed distance,
/// a point of a's boundary and one of b's (x, y, z of each), then, from the library, its distance
/// and point error.

}  // namespace cc::harness
