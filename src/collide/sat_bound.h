// The bound of the triangle queries' separating-axis tests (separating_axis.h), and its record.
#pragma once

#include "collide/aabb.h"
#include "collide/fp.h"
#include "collide/record_sink.h"
#include "collide/triangle.h"

namespace cc::bounds {

/// The gap between the projections of two sets onto an axis is certified against total().
struct SatBound {
  double axis_norm1;                // |axis|_1
  double magnitude_a, magnitude_b;  // the sets' largest absolute coordinates
  double perturbation_per_unit;     // how far each coordinate may be off before (a change of frame)
  /// Each projected end is off by at most 3u |axis|_1 magnitude (a product and two additions per
  /// term), the gap adds one rounding: 5u covers both and the bound's own rounding.
  double projection_per_unit() const { return 5 * fp::u * (magnitude_a + magnitude_b); }
  double projection() const { return axis_norm1 * projection_per_unit(); }
  double perturbation() const { return axis_norm1 * perturbation_per_unit; }
  double total() const { return axis_norm1 * (projection_per_unit() + perturbation_per_unit) + fp::subnormal_slack; }
};

/// The gap between the projections of set a (a triangle, or the box [box.lo, box.hi]) and of
/// triangle b onto `axis`, as computed.
struct SatAxis {
  Vec3 axis;
  bool a_is_box = false;
  Triangle a_triangle;
  Aabb a_box;
  Triangle b;
  double gap = 0;
  SatBound bound;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (triangle_box.h), recording its certified quantities into `records`
/// (bound_records.h); the same answer, bit for bit.
bool test_triangle_aabb(const Triangle& t, const Aabb& box, bounds::Records& records);

}  // namespace cc
