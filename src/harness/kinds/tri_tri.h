// tri_tri: two triangles, test_triangle_triangle.
#pragma once

#include "harness/formats/parts.h"

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
