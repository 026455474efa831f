// Collision determination for two triangles: where they meet, as a point, a segment or a convex
// polygon.
#pragma once

#include <array>

#include "collide/triangle.h"

namespace cc {

/// The corners of a convex set: none (empty), one point, the two ends of a segment, or the 3 to 6
/// corners of a polygon in order around it.
struct TriangleIntersection {
  std::array<Vec3, 6> points{};
  int count = 0;
  bool empty() const { return count == 0; }
};

/// Where the closed triangles a and b meet: the corners of a n b.
///  - Exact topology: empty exactly when they share no point, decided with exact orientation
///    signs (exact_orientation.h). Touching at a vertex gives that vertex, along an edge the
///    touching segment; which corners there are is decided exactly too: a vertex of one triangle
///    in the other, an edge of one crossing the other, and, for coplanar triangles, two edges
///    crossing.
///  - A corner that is a vertex of a or b is reported as given. A corner where an edge crosses
///    the other triangle's plane, or two edges cross in a common plane, is rounded: it lies within
///    2^-44 M kappa + 2^-1074 of the exact corner, where M is the largest coordinate magnitude of
///    the six vertices and kappa (at least 1) the corner's condition number:
///      c_t / sin phi for an edge crossing the plane of triangle t at the angle phi,
///      c / sin psi for two edges crossing at the angle psi in a common plane, c the larger c_t of
///      the triangles among a and b (1 for two segments),
///    with c_t = L^2 / |n| (L the longest edge of t, n the cross product of two of its edges): a
///    sliver's plane is ill-determined. So the hull of the points lies within that distance of
///    a n b, and a n b within it of the hull (Hausdorff distance).
///  - Degenerate triangles are their point sets (a segment, a point), by the same rules.
///  - Symmetric in a and b bit for bit (the same points in the same order).
///  - Domain: finite coordinates of magnitude at most 2^300 (the rounded corners need products of
///    three coordinates). NaN or infinite input: empty.
TriangleIntersection intersect_triangles(const Triangle& a, const Triangle& b);

}  // namespace cc
