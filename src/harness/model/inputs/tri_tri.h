// The input of tri_tri and its fields; the kind's unit is src/harness/kinds/tri_tri.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

struct TriTriInput {
  Triangle a, b;
  friend bool operator==(const TriTriInput&, const TriTriInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<TriTriInput> {
  static constexpr auto list = std::tuple{field<&TriTriInput::a>("a"), field<&TriTriInput::b>("b")};
};

}  // namespace cc::harness
