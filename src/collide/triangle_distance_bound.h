// The bound of distance_triangle_triangle's witnesses (triangle_distance.h), and its probing
// overload. Its distance's bound is certified after the fact (separation.h), from the witnesses
// and a gap along a direction; the witnesses' is this one.
#pragma once

#include "collide/fp.h"
#include "collide/separation.h"
#include "collide/triangle.h"

namespace cc::bounds {

/// distance_triangle_triangle's witnesses, with `magnitude` the largest vertex coordinate M.
struct TriangleDistanceBound {
  double magnitude;
  /// Each witness is v0 + s (v1 - v0) for an edge (s in [0, 1]) or v0 + s e1 + t e2 for a face
  /// (s, t >= 0, s + t <= 1, as computed): each edge vector rounds u of 2M, each product u of 2M
  /// and carries its vector's error (2uM in all, as s + t <= 1), each sum u of at most 3M: within
  /// 12uM per coordinate, 20.8uM in length; 32uM leaves room for s + t exceeding 1 by its own
  /// rounding.
  double point_rounding() const { return 32 * fp::u * magnitude; }
  double point() const { return point_rounding() + fp::subnormal_slack; }
};

/// A call of distance_triangle_triangle and its answer, as computed.
struct TriangleSeparation {
  Triangle a, b;
  Separation answer;
  TriangleDistanceBound bound;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (triangle_distance.h), recording the call and its bounds into
/// `records` (bound_records.h); the same answer, bit for bit.
Separation distance_triangle_triangle(const Triangle& a, const Triangle& b, bounds::Records& records);

}  // namespace cc
