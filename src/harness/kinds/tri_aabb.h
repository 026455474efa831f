// tri_aabb: a triangle against an axis-aligned box, test_triangle_aabb.
#pragma once

#include "harness/formats/parts.h"

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
