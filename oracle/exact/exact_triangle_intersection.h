// Where two closed triangles meet, in exact arithmetic: the corners of their intersection, and how
// well conditioned the library's rounded value of each corner is (collide/triangle_intersection.h).
// By clipping, not by the library's enumeration of vertices and crossings: a is cut by the two
// sides of b's plane and the three planes through b's edges perpendicular to it.
#pragma once

#include <vector>

#include "collide/triangle.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

/// A corner of the intersection, and kappa, the condition number of the library's rounded corner
/// there (its bound is 2^-44 M kappa): 1 for a vertex of a triangle; for a point of an edge
/// crossing a triangle's plane at the angle phi, c / sin phi, c = L^2 / |n| for that triangle
/// (L its longest edge, n its edge cross product); for two edges crossing at the angle psi in a
/// common plane, c / sin psi, c the larger of the triangles' (1 for two segments). Where several
/// constructions give the corner, the largest.
struct ExactCorner {
  QVec3 point;
  double condition = 1;
};

/// The corners of a n b for finite closed triangles, degenerate ones included (segments, points):
/// none, a point, a segment's two ends, or a coplanar polygon's corners (in no particular order).
std::vector<ExactCorner> exact_triangle_intersection(const Triangle& a, const Triangle& b);

/// The squared distance from p to the convex hull of coplanar points (1 to 6 of them; 0 for none).
Rational distance2_to_hull(const QVec3& p, const std::vector<QVec3>& points);

}  // namespace cc::exact
