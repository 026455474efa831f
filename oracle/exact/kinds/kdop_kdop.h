// The exact k-DOPs of two point sets, shared by the verdict and the explanation.
#pragma once

#include <vector>

#include "harness/model/input.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

struct ExactSlab {
  Rational a_lo, a_hi, b_lo, b_hi;
  Rational overlap;  // min(a_hi, b_hi) - max(a_lo, b_lo): < 0 separates
  double length;     // of the slab's direction
};

/// One slab per direction of kdop_directions(in.k); requires non-empty, finite point sets.
std::vector<ExactSlab> exact_kdop_slabs(const harness::KdopKdopInput& in);

}  // namespace cc::exact
