// moving_obb: two boxes moving with constant velocities over a step, sweep_obb_obb.
#pragma once

#include "collide/moving_box.h"

namespace cc::harness {

/// Two boxes moving with constant velocities over a step: whether they meet, and when first
/// and last.
struct MovingObbInput {
  MovingObb a, b;
  friend bool operator==(const MovingObbInput&, const MovingObbInput&) = default;
};

}  // namespace cc::harness
