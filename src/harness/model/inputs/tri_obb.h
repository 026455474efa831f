// The input of tri_obb and its fields; the kind's unit is src/harness/kinds/tri_obb.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct TriObbInput {
  Triangle tri;
  Obb box;
  friend bool operator==(const TriObbInput&, const TriObbInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<TriObbInput> {
  static constexpr auto list = std::tuple{field<&TriObbInput::tri>("triangle"), field<&TriObbInput::box>("box")};
};

}  // namespace cc::harness
