// How far apart two small convex sets given by their corners are: the Hausdorff distance between
// their convex hulls, for judging the corners of an intersection (Judged::corners).
#pragma once

#include <span>

#include "collide/vec3.h"

namespace cc::harness {

/// The distance from p to the convex hull of coplanar points (1 to 12 of them), in floating point:
/// the least distance to a triangle of three of them (every point of a plane hull lies in one).
/// Its rounding error is a few units in the last place of the coordinates' magnitude.
double distance_to_hull(const Vec3& p, std::span<const Vec3> points);

/// max(the farthest of a's points from b's hull, the farthest of b's from a's): the Hausdorff
/// distance between the hulls (each a convex set's farthest point from a convex set is a corner).
/// Measured on copies scaled by a power of two to a largest magnitude of about 1 (no squares
/// underflow). Infinite when exactly one set is empty or a coordinate is not finite; 0 when both
/// are empty.
double hull_distance(std::span<const Vec3> a, std::span<const Vec3> b);

}  // namespace cc::harness
