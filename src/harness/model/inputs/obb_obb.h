// The input of obb_obb and its fields; the kind's unit is src/harness/kinds/obb_obb.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct ObbObbInput {
  Obb a, b;
  friend bool operator==(const ObbObbInput&, const ObbObbInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<ObbObbInput> {
  static constexpr auto list = std::tuple{field<&ObbObbInput::a>("a"), field<&ObbObbInput::b>("b")};
};

}  // namespace cc::harness
