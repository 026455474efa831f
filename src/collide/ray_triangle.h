// Rays and segments against triangles, by conservative slabs.
#pragma once

#include "collide/ray.h"
#include "collide/triangle.h"

namespace cc {

/// Where a ray first meets a triangle: on a hit, the parameter t of that point.
struct RayTriangleHit {
  bool hit = false;
  double t = 0;
};

/// How close to a triangle intersect_ray_triangle may put its reported point, relative to R:
/// 2^-44 (see there).
inline constexpr double kRayTriangleTolerance = 0x1p-44;

/// Intersects a ray (or a segment, see Ray) with a closed triangle: whether some point
/// origin + t * dir with t in [tmin, tmax] lies in the triangle, and the smallest such t.
/// The ray is clipped against slabs that contain the triangle in exact arithmetic (its plane,
/// its edges' in-plane normals, its edges, and the planes through the direction and an edge),
/// each slab widened by a bound on its rounding error.
///  - Conservative: a ray that touches the triangle in exact arithmetic (through its inside,
///    an edge or a vertex, grazing it, or lying in its plane) is always a hit, and then t is
///    never later than the exact first parameter t*: tmin <= t <= t*.
///  - Tolerance: on a hit the point origin + t * dir lies, in exact arithmetic, within
///    kRayTriangleTolerance * R of the triangle (Euclidean distance), where R is the largest
///    |v[k] - origin| over the vertices and the axes. So a ray that misses by less than that
///    may be reported as a hit, and for a ray that crosses the triangle's plane at the angle
///    theta, t* - t <= kRayTriangleTolerance * R / (|dir| sin theta). (The bound has a margin:
///    against an exact reference on random, touching and grazing cases, at most 2^-47.6 R.)
///  - Coplanar: a ray in the triangle's plane is clipped against the edges; t is where it
///    enters the triangle, tmin when it starts inside. A ray parallel to the plane and off it
///    by more than the tolerance misses.
///  - Degenerate triangles are valid and are hit as the segments or points they are.
///  - dir = 0 tests the origin alone (t = tmin on a hit); a tiny or huge dir is as good as a
///    unit one (it is scaled by a power of two). tmin < 0 is allowed: t is then the first
///    point of the whole range, which may be negative.
///  - Domain: finite coordinates of magnitude at most 2^300. NaN anywhere, an infinite
///    coordinate, tmin > tmax, tmin = +inf or tmax = -inf give no hit.
RayTriangleHit intersect_ray_triangle(const Ray& ray, const Triangle& triangle);

}  // namespace cc
