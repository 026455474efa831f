// tri_aabb: a triangle against an axis-aligned box, test_triangle_aabb.
#pragma once

#include "collide/aabb.h"
#include "collide/triangle.h"

namespace cc::harness {

struct TriAabbInput {
  Triangle tri;
  Aabb box;
  friend bool operator==(const TriAabbInput&, const TriAabbInput&) = default;
};

}  // namespace cc::harness
