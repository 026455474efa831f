// tri_obb: a triangle against an oriented box, test_triangle_obb.
#pragma once

#include "collide/obb.h"
#include "collide/triangle.h"

namespace cc::harness {

struct TriObbInput {
  Triangle tri;
  Obb box;
  friend bool operator==(const TriObbInput&, const TriObbInput&) = default;
};

}  // namespace cc::harness
