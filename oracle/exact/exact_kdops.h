// The exact k-DOPs of two point sets, slab by slab: what the k-DOP query's verdict, its explanation
// and the audit by CGAL (oracle/cgal) compare.
#pragma once

#include <vector>

#include "collide/vec3.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

struct ExactSlab {
  Rational a_lo, a_hi, b_lo, b_hi;
  Rational overlap;  // min(a_hi, b_hi) - max(a_lo, b_lo): < 0 separates
  double length;     // of the slab's direction
};

/// One slab per direction of kdop_directions(k), in its order: the least and greatest exact
/// projection of each set onto the direction. Requires non-empty sets of finite points and a k
/// with a direction set (none for another k).
std::vector<ExactSlab> exact_kdop_slabs(int k, const std::vector<Vec3>& a, const std::vector<Vec3>& b);

}  // namespace cc::exact
