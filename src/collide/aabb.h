// Axis-aligned bounding boxes.
#pragma once

#include "collide/vec3.h"

namespace cc {

/// The closed box [lo.x, hi.x] x [lo.y, hi.y] x [lo.z, hi.z]. A box with lo == hi on an axis
/// has zero extent there (a rectangle, a segment or a point) and is still a valid box.
struct Aabb {
  Vec3 lo, hi;
  friend constexpr bool operator==(const Aabb&, const Aabb&) = default;
};

/// True when the closed boxes share at least one point: on every axis a.lo <= b.hi and
/// b.lo <= a.hi. Exact: it only compares inputs.
///  - Touching at a face, an edge or a corner: true. Zero-extent boxes take part as the
///    rectangles, segments or points they are.
///  - NaN in any bound: false (every comparison with NaN is false).
///  - Infinite bounds compare as extended reals (a box may be unbounded).
///  - Out of contract, an inverted box (lo > hi on an axis) is not treated as empty: the answer
///    is still the per-axis comparison above.
inline bool test_aabb_aabb(const Aabb& a, const Aabb& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x &&  //
         a.lo.y <= b.hi.y && b.lo.y <= a.hi.y &&  //
         a.lo.z <= b.hi.z && b.lo.z <= a.hi.z;
}

}  // namespace cc
