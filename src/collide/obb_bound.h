// The bound of test_obb_obb and sweep_obb_obb (obb.h, moving_box.h), and their records.
#pragma once

#include "collide/fp.h"
#include "collide/moving_box.h"
#include "collide/obb.h"
#include "collide/record_sink.h"

namespace cc::bounds {

/// An axis separates when |projection| - (radius_a + radius_b) exceeds total() (in the units of
/// the axis as computed, not normalised).
struct ObbBound {
  double offset;              // |d|_1 of the centres' offset (sweep: |d|_1 + |v|_1)
  double extent_a, extent_b;  // the sums of the half extents
  /// Rounding: at most 22u offset + 8u (extents) on the worst (edge) axis; 32u covers it and the
  /// bound's own evaluation.
  double rounding() const { return 32 * fp::u * fp::sum3(offset, extent_a, extent_b); }
  /// Axes orthonormal only to within the tolerance change the radii by at most 4 tolerance
  /// (extents); 6 is used.
  double frame() const { return 6 * kObbOrthonormalTolerance * (extent_a + extent_b); }
  double total() const { return rounding() + frame() + fp::subnormal_slack; }
};

/// The boxes (velocities 0 for the static test) and the bound of every axis; the axes follow
/// (ObbAxis).
struct ObbTest {
  MovingObb a, b;
  ObbBound bound;
};

/// One axis of an ObbTest: 0-2 a's face normals, 3-5 b's, 6 + 3i + j the edge axis a_i x b_j,
/// computed in a's frame (frame 0) or in b's (frame 1). The projection of the centres' offset
/// at t = 0 and its rate (0 for the static test), and the radii, as computed.
struct ObbAxis {
  int axis = 0;
  int frame = 0;
  double projection = 0, rate = 0, radius_a = 0, radius_b = 0;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (obb.h), recording its certified quantities into `records`
/// (bound_records.h); the same answer, bit for bit.
bool test_obb_obb(const Obb& a, const Obb& b, bounds::Records& records);

/// The same as its plain version (moving_box.h), recording its certified quantities into `records`
/// (bound_records.h); the same answer, bit for bit.
SweepHit sweep_obb_obb(const MovingObb& a, const MovingObb& b, bounds::Records& records);

}  // namespace cc
