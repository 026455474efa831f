// The bound of test_triangle_obb's change of frame (triangle_box.h), and its record.
#pragma once

#include "collide/fp.h"
#include "collide/obb.h"
#include "collide/record_sink.h"
#include "collide/triangle.h"

namespace cc::bounds {

/// The triangle taken into the box's frame (A^T (v - centre)), and the box's faces there, are
/// each off by at most total() per coordinate.
struct FrameChangeBound {
  double reach;     // the largest |v - centre|_1
  double half_sum;  // the sum of the half extents
  /// Each local coordinate is a difference, three products and two additions away from exact:
  /// 4u |v - c|_1, 5u used.
  double rounding() const { return 5 * fp::u * reach; }
  /// Axes orthonormal to within the tolerance move the box's faces in that frame by at most
  /// tolerance * half_sum; 2 used.
  double orthonormality() const { return 2 * kObbOrthonormalTolerance * half_sum; }
  double total() const { return rounding() + orthonormality() + fp::subnormal_slack; }
};

/// The triangle taken into the box's frame, as computed.
struct FrameChange {
  Triangle world;
  Obb box;
  Triangle local;
  FrameChangeBound bound;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (triangle_box.h), recording its certified quantities into `records`
/// (bound_records.h); the same answer, bit for bit.
bool test_triangle_obb(const Triangle& t, const Obb& box, bounds::Records& records);

}  // namespace cc
