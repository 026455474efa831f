// The input of tri_tri_intersection and its fields; the kind's unit is src/harness/kinds/tri_tri_intersection.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct TriTriIntersectionInput {
  Triangle a, b;
  friend bool operator==(const TriTriIntersectionInput&, const TriTriIntersectionInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<TriTriIntersectionInput> {
  static constexpr auto list =
      std::tuple{field<&TriTriIntersectionInput::a>("a"), field<&TriTriIntersectionInput::b>("b")};
};

/// The answer: hit when the triangles meet, and the corners of a n b as params (x, y, z of each).

}  // namespace cc::harness
