// The signed distance between two convex polytopes in exact rational arithmetic, from the exact
// convex hull of their Minkowski difference: the reference for the library's box distances and
// depths (collide/obb_distance.h, collide/triangle_box_distance.h), independent of how the library finds them.
#pragma once

#include <array>
#include <span>

#include "collide/obb.h"
#include "collide/triangle.h"
#include "oracle/exact/distance_check.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

/// The eight corners of a box (the parallelepiped its axes span, as given), exactly.
std::array<QVec3, 8> box_corners(const Obb& box);

/// The three vertices of a triangle, exactly.
std::array<QVec3, 3> triangle_corners(const Triangle& t);

/// The signed distance between the convex hulls of a's points and b's (each non-empty), as the
/// signed distance from the origin to the boundary of M = a - b, the hull of every difference:
///  - the origin outside M (the polytopes apart): the least squared distance to M's faces, sign +1;
///  - the origin inside M (overlapping): the least squared distance to the planes of M's faces,
///    sign -1 (the penetration depth: the shortest translation of b that separates them);
///  - the origin on M's boundary (touching), or M without an inside (flat, a segment, a point)
///    holding it: 0.
/// M's hull is built exactly (incremental, every predicate decided in rationals); a flat M is
/// hulled in its plane.
ExactSignedDistance exact_polytope_distance(std::span<const QVec3> a, std::span<const QVec3> b);

}  // namespace cc::exact
