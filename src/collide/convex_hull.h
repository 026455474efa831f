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
/// `vertices` holds every point on the hull's boundary at least once (for flat input it may hold
/// points inside the polygon too); for collinear input, the two extreme points; for coincident
/// input, one point. Extremes of any linear function over the points are reached at `vertices`.
/// Points must be finite.
struct ConvexHull {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> vertices;
};

ConvexHull convex_hull(std::span<const Vec3> points);

}  // namespace cc
