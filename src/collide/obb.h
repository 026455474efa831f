// Oriented bounding boxes.
#pragma once

#include "collide/vec3.h"

namespace cc {

/// The closed box { center + axes * u : |u_i| <= half_i }. The columns of `axes` are the box's
/// axes; they must be orthonormal to within kObbOrthonormalTolerance (every entry of
/// axes^T axes - I at most that in magnitude). A half extent of 0 makes the box flat, a segment
/// or a point.
struct Obb {
  Vec3 center;
  Vec3 half;
  Mat3 axes;
  friend constexpr bool operator==(const Obb&, const Obb&) = default;
};

/// What every query on boxes asks of a box (some ask more: a bound on the magnitude): its centre,
/// half extents and axes finite (one comparison: x - x is 0 only for a finite x), no half extent
/// negative (0 is a flat box). NaN anywhere: false. Orthonormal axes are the caller's promise.
inline bool in_domain(const Obb& b) {
  const Vec3 zero = ((b.center - b.center) + (b.half - b.half)) +
                    ((b.axes.col[0] - b.axes.col[0]) + (b.axes.col[1] - b.axes.col[1]) + (b.axes.col[2] - b.axes.col[2]));
  return finite(zero) && b.half.x >= 0 && b.half.y >= 0 && b.half.z >= 0;
}

/// How far from orthonormal the axes of an Obb may be: 2^-48, which a rotation computed in
/// double precision from a unit quaternion, or a product of a few such, satisfies.
inline constexpr double kObbOrthonormalTolerance = 0x1p-48;

/// True when the closed boxes share a point. Separating-axis test on the 15 axes of Gottschalk
/// et al.: the 3 face normals of each box and the 9 cross products of their edges, evaluated in
/// a's frame and in b's frame (so the test is symmetric in a and b bit for bit).
///  - Conservative: an axis separates only when the gap on it exceeds a bound on the rounding
///    error and on the deviation of the axes from orthonormal. Touching boxes are always
///    reported; boxes apart by less than 2^-40 of the largest centre or extent coordinate may be.
///  - Nearly parallel edges: their cross product is nearly zero, so both the gap and the radii
///    on that axis are nearly zero and the error bound keeps the axis from separating; the
///    face axes decide. No epsilon is added to the rotation entries.
///  - Zero extents are exact: flat boxes, segments and points are handled as such.
///  - Domain: finite inputs of magnitude at most 2^500, half extents >= 0, axes orthonormal to
///    within the tolerance. NaN or infinite input, or a negative half extent: false. Axes
///    further from orthonormal: the answer is that of the same arithmetic, unchecked.
bool test_obb_obb(const Obb& a, const Obb& b);

}  // namespace cc
