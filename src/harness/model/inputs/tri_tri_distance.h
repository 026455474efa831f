// The input of tri_tri_distance and its fields; the kind's unit is src/harness/kinds/tri_tri_distance.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct TriTriDistanceInput {
  Triangle a, b;
  friend bool operator==(const TriTriDistanceInput&, const TriTriDistanceInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<TriTriDistanceInput> {
  static constexpr auto list =
      std::tuple{field<&TriTriDistanceInput::a>("a"), field<&TriTriDistanceInput::b>("b")};
};

/// The answer: hit when the triangles meet (distance 0), and as params the distance, a point of
/// a and a point of b (x, y, z of each), then, from the library, its distance and point error.

}  // namespace cc::harness
