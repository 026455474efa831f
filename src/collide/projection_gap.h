// A certified lower bound on the distance between two convex hulls of points, from one
// direction: the gap between their projections on it.
#pragma once

#include <span>

#include "collide/vec3.h"

namespace cc {

/// The gap between the projections of a's points and b's points on `direction` (b's least
/// minus a's greatest) over its length, less its rounding bound; 0 where the projections
/// overlap. For any direction it is at most the distance between the hulls of a and b, and it
/// is the distance, but for the rounding bound, along the direction of a closest pair. A zero
/// or non-finite direction, or an empty list, gives 0. Finite points of magnitude at most 2^500.
double projection_gap(std::span<const Vec3> a, std::span<const Vec3> b, const Vec3& direction);

}  // namespace cc
