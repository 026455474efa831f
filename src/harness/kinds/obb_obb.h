// obb_obb: two oriented boxes, test_obb_obb.
#pragma once

#include "collide/obb.h"

namespace cc::harness {

struct ObbObbInput {
  Obb a, b;
  friend bool operator==(const ObbObbInput&, const ObbObbInput&) = default;
};

}  // namespace cc::harness
