// Distances in exact rational arithmetic, as squares (no square root is ever rounded): a point to
// an oriented box (the parallelepiped its axes span, as given) and inside one to its boundary, a
// point to a segment and to a triangle, segment to segment, triangle to triangle. The reference
// for the library's distance queries (collide/separation.h).
#pragma once

#include <array>

#include "collide/obb.h"
#include "collide/segment.h"
#include "collide/triangle.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

/// The box's coordinates of a point: q with point = center + axes q (the axes as given, which
/// need not be orthonormal; they must be independent, or this throws std::domain_error).
QVec3 box_coordinates(const QVec3& point, const Obb& box);

/// Whether the point lies in the closed box.
bool in_box(const QVec3& point, const Obb& box);

/// The squared distance from the point to the closed box: 0 inside. The least of |axes q - d|^2
/// over the 27 ways to hold each coordinate of q at -half, at +half or free, the free ones
/// solving their normal equations, among those that lie in the box.
Rational squared_distance_to_box(const QVec3& point, const Obb& box);

/// The squared distance from a point of the closed box to the box's boundary: the least squared
/// distance to the planes of its six faces (each spanned by two axes). 0 on the boundary, and
/// for a flat box.
Rational squared_depth_in_box(const QVec3& point, const Obb& box);

/// A triangle with rational vertices (a triangle placed exactly by a pose, say).
using QTriangle = std::array<QVec3, 3>;
QTriangle rational_triangle(const Triangle& t);

/// The squared distance from a point to a closed segment (a point when its ends coincide).
Rational squared_distance_to_segment(const QVec3& point, const Segment& segment);
Rational squared_distance_to_segment(const QVec3& point, const QVec3& from, const QVec3& to);

/// The squared distance between two closed segments: the least of the four ends against the
/// other segment and, when the segments are not parallel, of the pair of interior points whose
/// difference is perpendicular to both, if that pair lies on both.
Rational squared_distance_between_segments(const Segment& a, const Segment& b);

/// The squared distance from a point to a closed triangle (degenerate: the segment or point it
/// is): the foot on its plane when that lies in it, else the nearest of its edges.
Rational squared_distance_to_triangle(const QVec3& point, const Triangle& triangle);
Rational squared_distance_to_triangle(const QVec3& point, const QTriangle& triangle);

/// The squared distance between two closed triangles: 0 when an edge of either meets the other
/// (a triangle that is not degenerate), else the least over each vertex against the other
/// triangle and each pair of edges.
Rational squared_distance_between_triangles(const Triangle& a, const Triangle& b);
Rational squared_distance_between_triangles(const QTriangle& a, const QTriangle& b);

/// Whether |x - y| <= e where x^2 = square (x >= 0) and y, e are rationals: x lies in
/// [y - e, y + e], decided on squares.
bool root_within(const Rational& square, const Rational& y, const Rational& e);

}  // namespace cc::exact
