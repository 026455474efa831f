// Facts about shapes as given, in floating point, for recognising configurations (features.h,
// configurations.h): zero, parallel and nearly parallel vectors, a triangle's edges and normal,
// degenerate triangles and boxes, frames off orthonormal.
#pragma once

#include <algorithm>
#include <cmath>

#include "collide/aabb.h"
#include "collide/length.h"  // length(v), without overflow or underflow
#include "collide/triangle.h"

namespace cc::harness {

/// An edge or axis this much (sine of the angle, not 0) from another is nearly parallel to it.
inline constexpr double kNearlyParallel = 0x1p-20;

inline bool is_zero(const Vec3& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

/// Two nonzero vectors with a zero cross product (as computed; exact for the simple values the
/// generators use to build parallel configurations).
inline bool parallel(const Vec3& a, const Vec3& b) { return !is_zero(a) && !is_zero(b) && is_zero(cross(a, b)); }

/// The sine of the angle between two nonzero vectors (0 for a zero one).
inline double sine(const Vec3& a, const Vec3& b) {
  const double la = length(a), lb = length(b);
  return la > 0 && lb > 0 ? length(cross(a, b)) / (la * lb) : 0;
}
inline bool nearly_parallel(const Vec3& a, const Vec3& b) {
  const double s = sine(a, b);
  return s > 0 && s <= kNearlyParallel;
}

/// Edge i of a triangle, from vertex i to the next, and its normal (edge 0 x edge 1).
inline Vec3 edge(const Triangle& t, int i) { return t.v[static_cast<std::size_t>((i + 1) % 3)] - t.v[static_cast<std::size_t>(i)]; }
inline Vec3 normal(const Triangle& t) { return cross(edge(t, 0), edge(t, 1)); }

/// Two triangles in one plane, as computed: parallel normals and b's vertices on a's plane.
inline bool coplanar(const Triangle& a, const Triangle& b) {
  const Vec3 na = normal(a);
  bool in_plane = parallel(na, normal(b));
  for (const Vec3& p : b.v) in_plane &= dot(na, p - a.v[0]) == 0;
  return in_plane;
}

/// An edge of a parallel to an edge of b.
inline bool parallel_edges(const Triangle& a, const Triangle& b) {
  bool any = false;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) any |= parallel(edge(a, i), edge(b, j));
  }
  return any;
}
inline double longest_edge(const Triangle& t) { return std::max({length(edge(t, 0)), length(edge(t, 1)), length(edge(t, 2))}); }
inline double max_coordinate(const Triangle& t) { return std::max({max_abs(t.v[0]), max_abs(t.v[1]), max_abs(t.v[2])}); }

/// A triangle of zero area (a segment or a point), as computed from its first vertex.
inline bool degenerate(const Triangle& t) { return is_zero(cross(t.v[1] - t.v[0], t.v[2] - t.v[0])); }
inline bool is_point(const Triangle& t) { return t.v[0] == t.v[1] && t.v[1] == t.v[2]; }
inline bool is_segment(const Triangle& t) { return !is_point(t) && normal(t) == Vec3{}; }

/// A triangle edge or normal parallel to one of the given axes.
inline bool parallel_to_axes(const Triangle& t, const Mat3& axes) {
  const Vec3 n = normal(t);
  for (const Vec3& a : axes.col) {
    if (parallel(n, a)) return true;
    for (int i = 0; i < 3; ++i) {
      if (parallel(edge(t, i), a)) return true;
    }
  }
  return false;
}

/// A box with a zero extent on some axis; the number of zero half extents.
inline bool zero_extent(const Aabb& b) { return b.lo.x == b.hi.x || b.lo.y == b.hi.y || b.lo.z == b.hi.z; }
inline int zero_extents(const Vec3& half) { return (half.x == 0) + (half.y == 0) + (half.z == 0); }

/// The largest entry of axes^T axes - I.
inline double off_orthonormal(const Mat3& m) {
  double worst = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) worst = std::max(worst, std::fabs(dot(m.col[i], m.col[j]) - (i == j ? 1.0 : 0.0)));
  }
  return worst;
}

}  // namespace cc::harness
