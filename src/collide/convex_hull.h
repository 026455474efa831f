// Convex hulls of point sets in 3-D, computed by Qhull.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "collide/vec3.h"

namespace cc {

/// The boundary of the convex hull of a point set, as indices into the points.
///  - Full-dimensional points: the hull's facets, triangulated.
///  - Flat points (all in one plane, as the vertices of a single triangle or of a thin plate):
///    the hull is a polygon; `triangles` covers it twice, once per side, so that area-weighted
///    sums over the boundary are those of the polygon counted twice.
///  - Collinear or coincident points, or fewer than three: no triangles.
/// `vertices` holds every extreme point of the set (every vertex of its exact convex hull) at
/// least once, so the hull of `vertices` holds every point in exact arithmetic and the extremes
/// of any linear function over the points are reached at `vertices`. It may hold points on the
/// boundary or near it too (for flat input, every point). Exactly collinear points give exactly
/// the two ends (the least and the greatest in lexicographic order), coincident points one
/// point, no points none. (Points so nearly collinear that no plane through them can be
/// computed give every point and no triangles; so do collinear points with a nonzero
/// coordinate below 2^-900 of the largest, where collinearity is not decided exactly.)
/// Points must be finite.
struct ConvexHull {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> vertices;
};

ConvexHull convex_hull(std::span<const Vec3> points);

/// The same shape in floating point, fast (quickhull, O(n log n) expected, no library call), for
/// fitting (an OBB's axes from the hull's surface) and for the points a hull keeps:
///  - `triangles`: a closed surface of facets whose vertices are among the points, convex up to
///    rounding (a point within 2^-40 of the points' extent plus 2^-44 of their magnitude of a
///    facet's plane counts as inside it); flat points: the polygon, covered on both sides;
///    collinear or coincident: none.
///  - `vertices`: every point the hull may need, in exact arithmetic: a point is left out only
///    when it lies, certainly, strictly inside a tetrahedron of points kept (four orientation
///    signs certified by the filter of exact_orientation.h). So the hull of `vertices` holds
///    every point exactly. Flat and collinear points: all of them.
/// Points must be finite and distinct (repeated points are harmless but slow it down).
ConvexHull fast_convex_hull(std::span<const Vec3> points);
/// The same, into `hull` (its storage reused: no allocation once it has grown).
void fast_convex_hull(std::span<const Vec3> points, ConvexHull& hull);

}  // namespace cc
