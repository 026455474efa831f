// The exact separating-axis test of boxes and triangles given in doubles, filtered: the verdict
// and the margin of exact_sat (convex_sat.h) bit for bit, with exact arithmetic only where
// floating point cannot place an axis, and then on integers (dyadic.h) rather than rationals.
#pragma once

#include <string>
#include <variant>

#include "collide/aabb.h"
#include "collide/obb.h"
#include "collide/triangle.h"
#include "oracle/exact/convex_sat.h"
#include "oracle/exact/triangle_sat.h"

namespace cc::exact {

/// A convex shape as the kinds give it: a box [lo, hi] (lo <= hi), a parallelepiped (an Obb: its
/// matrix need not be orthonormal; half extents >= 0) or a triangle. Every coordinate finite.
using SatInput = std::variant<Aabb, Obb, Triangle>;

/// The exact shape of an input: box_shape, parallelepiped_shape or triangle_shape.
ExactShape exact_shape(const SatInput& s, const std::string& name);

/// exact_sat(exact_shape(a, "A"), exact_shape(b, "B")): the same hit, rank and margin, bit for
/// bit. Where the edge directions certainly span space, each candidate axis is placed in
/// floating point, every quantity carrying a bound on its error (bounded.h); exactly, on
/// integers, only the axes it cannot place: a cross product that may vanish, a gap whose sign is
/// within its bound, and the axes whose margin may be the extreme one (the margin is rounded
/// from the exact gap). Everything else (flat and lower-rank pairs, overflow, squares that
/// underflow) goes to exact_sat whole.
TriangleSatVerdict sat_verdict(const SatInput& a, const SatInput& b);

/// What this thread's sat_verdict calls did: decided by the filter, or by exact_sat whole, and
/// how many axes the filter had to take exactly.
struct SatFilterCounts {
  long filtered = 0, whole = 0, exact_axes = 0;
};
SatFilterCounts sat_filter_counts();

}  // namespace cc::exact
