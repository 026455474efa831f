// The input of aabb_aabb and its fields; the kind's unit is src/harness/kinds/aabb_aabb.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct AabbAabbInput {
  Aabb a, b;
  friend bool operator==(const AabbAabbInput&, const AabbAabbInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<AabbAabbInput> {
  static constexpr auto list = std::tuple{field<&AabbAabbInput::a>("a"), field<&AabbAabbInput::b>("b")};
};

}  // namespace cc::harness
