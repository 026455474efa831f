// The input of moving_obb and its fields; the kind's unit is src/harness/kinds/moving_obb.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

/// Two boxes moving with constant velocities over a step: whether they meet, and when first
/// and last.
struct MovingObbInput {
  MovingObb a, b;
  friend bool operator==(const MovingObbInput&, const MovingObbInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<MovingObbInput> {
  static constexpr auto list = std::tuple{field<&MovingObbInput::a>("a"), field<&MovingObbInput::b>("b")};
};

}  // namespace cc::harness
