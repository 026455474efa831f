// A box's frame as a proper rotation, for engines that take only rotations (quaternions, or
// contact code that assumes right-handed axes).
#pragma once

#include "collide/vec3.h"

namespace cc {

/// The same box frame with a positive determinant: a box is symmetric, so negating one axis of a
/// mirror-image frame (det < 0) leaves the box unchanged; any other frame (det >= 0, or NaN) is
/// returned as it is.
inline Mat3 proper_frame(const Mat3& axes) {
  const double det = dot(axes.col[0], cross(axes.col[1], axes.col[2]));
  if (!(det < 0)) return axes;
  return Mat3::from_columns(axes.col[0], axes.col[1], -axes.col[2]);
}

}  // namespace cc
