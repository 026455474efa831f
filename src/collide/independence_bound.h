// The bound of test_triangle_triangle's independence test (triangle_triangle.h), and its record.
#pragma once

#include "collide/fp.h"
#include "collide/record_sink.h"
#include "collide/triangle.h"
#include "collide/vec3.h"

namespace cc::bounds {

/// det(u, v, w) computed as (u x v) . w is nonzero beyond total().
struct IndependenceBound {
  double u_norm1, v_norm1, w_norm1;
  /// u x v is within 3u per component of |u|_1 |v|_1, the dot product adds 3u: 16u covers both
  /// and the bound's own rounding.
  double rounding() const { return 16 * fp::u * (u_norm1 * v_norm1) * w_norm1; }
  double total() const { return rounding() + fp::subnormal_slack; }
};

/// (u x v) . w as computed, from u x v as computed.
struct Independence {
  Vec3 u_cross_v, u, v, w;
  double det = 0;
  IndependenceBound bound;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (triangle_triangle.h), recording its certified quantities into `records`
/// (bound_records.h); the same answer, bit for bit.
bool test_triangle_triangle(const Triangle& a, const Triangle& b, bounds::Records& records);

}  // namespace cc
