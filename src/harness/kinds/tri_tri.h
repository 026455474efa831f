// tri_tri: two triangles, test_triangle_triangle.
#pragma once

#include "collide/triangle.h"

namespace cc::harness {

struct TriTriInput {
  Triangle a, b;
  friend bool operator==(const TriTriInput&, const TriTriInput&) = default;
};

}  // namespace cc::harness
