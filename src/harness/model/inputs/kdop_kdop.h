// The input of kdop_kdop and its fields; the kind's unit is src/harness/kinds/kdop_kdop.h.
#pragma once

#include <vector>

#include "harness/model/parts.h"

namespace cc::harness {

/// Two point sets, each fitted with a k-DOP; k is one of 6, 14, 16, 18, 24, 26.
struct KdopKdopInput {
  int k = 18;
  std::vector<Vec3> a, b;
  friend bool operator==(const KdopKdopInput&, const KdopKdopInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<KdopKdopInput> {
  static constexpr auto list = std::tuple{field<&KdopKdopInput::k, AsKdopK>("k"), field<&KdopKdopInput::a>("a"),
                                          field<&KdopKdopInput::b>("b")};
};

}  // namespace cc::harness
