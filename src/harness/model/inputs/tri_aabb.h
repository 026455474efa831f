// The input of tri_aabb and its fields; the kind's unit is src/harness/kinds/tri_aabb.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct TriAabbInput {
  Triangle tri;
  Aabb box;
  friend bool operator==(const TriAabbInput&, const TriAabbInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<TriAabbInput> {
  static constexpr auto list = std::tuple{field<&TriAabbInput::tri>("triangle"), field<&TriAabbInput::box>("box")};
};

}  // namespace cc::harness
