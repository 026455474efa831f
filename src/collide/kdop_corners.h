// The corners of a k-DOP, for re-fitting it after a rotation (Klosowski et al.'s approximation).
#pragma once

#include <vector>

#include "collide/kdop.h"

namespace cc {

/// The vertices of the k-DOP's polytope: the points where three slab planes with independent
/// normals meet and every other slab holds (to within 2^-46 of the bounds' magnitude, so a
/// corner is never lost to rounding; a near-corner just outside may be kept too). Computed in
/// floating point to within 2^-48 of the bounds' magnitude, and corners closer than 2^-49 of it
/// are kept once (fit_kdop's outward rounding bevels a corner into a speck of them), so their
/// convex hull contains the k-DOP up to 2^-46 of the magnitude. A flat k-DOP (lo == hi on a
/// slab) has the corners of the polygon, segment or point it is. Empty or NaN k-DOP: none.
template <int K>
std::vector<Vec3> kdop_corners(const Kdop<K>& dop);

}  // namespace cc
