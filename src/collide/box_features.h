// An oriented box as the distance queries take it apart: its projection on a direction, its
// face, edge or corner farthest along one, coordinates in its frame, and its point nearest a
// point given in them.
#pragma once

#include "collide/obb.h"
#include "collide/triangle.h"

namespace cc {

/// The radius of the box's projection on n: sum_k half_k |axis_k . n| (the parallelepiped's,
/// exactly, but for rounding: 6u |n| |half|_1). NaN in, NaN out.
double radius_along(const Obb& box, const Vec3& n);

/// The face, edge or corner of the box farthest along the unit direction n, every axis within
/// `tolerance` of perpendicular to n taken whole (the one most along n never), as triangles of
/// its corners (corners(box), obb_fit.h) moved by `shift`: two for a face, one degenerate for an
/// edge or a corner. Returns how many. Flat boxes give their degenerate faces as they are.
int farthest_feature(const Obb& box, const Vec3& n, double tolerance, const Vec3& shift, Triangle out[2]);

/// p's coordinates in the box's frame: axes^T (p - center), as computed.
Vec3 box_coordinates(const Obb& box, const Vec3& p);

/// The point of the box at the coordinates q clamped to its extents: the nearest point of the
/// box to the point with those coordinates (exactly so for orthonormal axes).
Vec3 clamped_into(const Obb& box, const Vec3& q);

/// A lower bound, up to rounding, on the squared distance from the segment between the box
/// coordinates p and q to the box, each axis's gap scaled by 2^-exponent: no point of the segment
/// is nearer on any axis. For pruning only; its rounding is not bounded.
double square_gap_to_box(const Obb& box, const Vec3& p, const Vec3& q, int exponent);

}  // namespace cc
