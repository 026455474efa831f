// An oriented box as the distance queries take it apart: its projection on a direction, its
// face, edge or corner farthest along one, coordinates in its frame, its point nearest a point
// given in them, and which of its features a set of points can be nearest to.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "collide/obb.h"
#include "collide/triangle.h"

namespace cc {

// radius_along, box_coordinates and clamped_into sum their three terms left to right
// (dot_in_order): a distance is judged on its certified bound, and the bounds hold for any order
// (fp.h).

/// The length of one of a box's axes, 1 long within 2^-48 in the domain: the root of its
/// squares summed in order, within 2.6u as length() gives it, with no scaling needed.
inline double axis_length(const Vec3& axis) { return std::sqrt(dot_in_order(axis, axis)); }

/// The radius of the box's projection on n: sum_k half_k |axis_k . n| (the parallelepiped's,
/// exactly, but for rounding: 6u |n| |half|_1). NaN in, NaN out.
inline double radius_along(const Obb& box, const Vec3& n) {
  return (box.half.x * std::fabs(dot_in_order(box.axes.col[0], n)) + box.half.y * std::fabs(dot_in_order(box.axes.col[1], n))) +
         box.half.z * std::fabs(dot_in_order(box.axes.col[2], n));
}

/// The 8 corners of the box, corner i at center + sum_k (bit k of i ? +1 : -1) half_k axis_k,
/// rounded (7u (|center|_inf + |half|_1) in length, as a product, two sums and the centre's
/// add); opposite corners are the centre plus and minus the same offset, exactly.
std::array<Vec3, 8> corners(const Obb& box);

/// The face, edge or corner of the box farthest along the unit direction n, every axis within
/// `tolerance` of perpendicular to n taken whole (the one most along n never), as triangles of
/// its corners (corners(box)) moved by `shift`: two for a face, one degenerate for an
/// edge or a corner. Returns how many. Flat boxes give their degenerate faces as they are.
int farthest_feature(const Obb& box, const Vec3& n, double tolerance, const Vec3& shift, Triangle out[2]);

/// p's coordinates in the box's frame: axes^T (p - center), as computed.
inline Vec3 box_coordinates(const Obb& box, const Vec3& p) {
  const Vec3 q = p - box.center;
  return {dot_in_order(box.axes.col[0], q), dot_in_order(box.axes.col[1], q), dot_in_order(box.axes.col[2], q)};
}

/// The coordinates q (in the box's frame) clamped to its extents, exactly.
inline Vec3 clamped(const Obb& box, const Vec3& q) {
  return {std::clamp(q.x, -box.half.x, box.half.x), std::clamp(q.y, -box.half.y, box.half.y),
          std::clamp(q.z, -box.half.z, box.half.z)};
}

/// The point of the box at the coordinates q clamped to its extents: the nearest point of the
/// box to the point with those coordinates (exactly so for orthonormal axes).
inline Vec3 clamped_into(const Obb& box, const Vec3& q) {
  const Vec3 c = clamped(box, q);
  const Mat3& m = box.axes;
  return box.center + ((c.x * m.col[0] + c.y * m.col[1]) + c.z * m.col[2]);
}

/// The componentwise least and largest of points (in a box's frame).
struct Extent {
  Vec3 lo, hi;
};
inline Extent extent_of(const Vec3& p, const Vec3& q) {
  return {{std::min(p.x, q.x), std::min(p.y, q.y), std::min(p.z, q.z)},
          {std::max(p.x, q.x), std::max(p.y, q.y), std::max(p.z, q.z)}};
}

/// The extent of the box's edge along axis k from its corner with index `corner` (bit i set for
/// +half_i), in the box's frame: [-half_k, half_k] on axis k, the corner's on the others.
inline Extent edge_extent(const Obb& box, int k, int corner) {
  Extent e;
  for (int i = 0; i < 3; ++i) e.lo[i] = e.hi[i] = (corner >> i & 1) ? box.half[i] : -box.half[i];
  e.lo[k] = -box.half[k], e.hi[k] = box.half[k];
  return e;
}

/// The squared gap between two extents, each axis's gap scaled by 2^-exponent: at most the squared
/// distance (scaled) between anything they hold, up to rounding. For pruning only.
inline double square_gap(const Extent& a, const Extent& b, int exponent) {
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    const double s = fp::scale2(std::max({0.0, a.lo[k] - b.hi[k], b.lo[k] - a.hi[k]}), -exponent);
    sum += s * s;
  }
  return sum;
}

/// Whether a point within e (in the box's frame) can have its nearest point of the box on the
/// box's corner with index `corner`, or on its edge from that corner along axis `along` (-1: the
/// corner): only if e reaches beyond the box's faces on the corner's side on every other axis
/// (clamping takes a point there), within `margin` for the frame's rounding. For pruning only.
inline bool reaches_beyond(const Obb& box, const Extent& e, int corner, int along, double margin) {
  for (int i = 0; i < 3; ++i) {
    if (i == along) continue;
    if ((corner >> i & 1) ? e.hi[i] + margin < box.half[i] : e.lo[i] - margin > -box.half[i]) return false;
  }
  return true;
}

}  // namespace cc
