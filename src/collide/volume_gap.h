// Certified lower bounds on the distance between two bounding volumes, for pruning a distance
// traversal (bvh_distance.h).
#pragma once

#include "collide/obb.h"
#include "collide/sphere.h"

namespace cc {

/// A lower bound on the distance between two closed balls: |b.center - a.center| - a.radius -
/// b.radius less its rounding, and 0 where that is not positive (they meet, or nearly).
/// Finite inputs of magnitude at most 2^500; NaN input gives 0 (nothing pruned on it).
double volume_gap(const Sphere& a, const Sphere& b);

/// A lower bound on the distance between two boxes (each the parallelepiped its axes span, so
/// axes need not be orthonormal): the largest gap between their projections on the line of the
/// centres and on the six axes, each less its rounding, and 0 where they all overlap (the boxes
/// meet, or are apart only along an edge-edge direction). Finite inputs of magnitude at most
/// 2^500; NaN input gives 0.
double volume_gap(const Obb& a, const Obb& b);

}  // namespace cc
