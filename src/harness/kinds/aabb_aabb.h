// aabb_aabb: two axis-aligned boxes, test_aabb_aabb.
#pragma once

#include "collide/aabb.h"

namespace cc::harness {

struct AabbAabbInput {
  Aabb a, b;
  friend bool operator==(const AabbAabbInput&, const AabbAabbInput&) = default;
};

}  // namespace cc::harness
