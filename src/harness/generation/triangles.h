// Triangles for the generators (triangles.cpp): generic and degenerate ones, triangles touching
// a box at a vertex or lying in a face's plane, triangles through flat boxes, and triangles in the
// regimes of the triangle tests' bounds slid to an exact margin.
#pragma once

#include <cmath>

#include "collide/aabb.h"
#include "collide/triangle.h"
#include "harness/generation/regimes.h"
#include "harness/generation/shapes.h"
#include "harness/model/input.h"

namespace cc::harness {

/// A triangle: generic, or degenerate (a segment, a point).
Triangle draw_triangle(ValueSource& values);
/// A triangle touching the box at one vertex (a corner, a point of an edge or of a face) or a few
/// ULPs off it on one axis, its other vertices outside the box, away from its centre.
Triangle triangle_touching_at_a_vertex(ValueSource& values, const Aabb& box);
/// A triangle against the box [box.lo, box.hi] (in the box's own frame): generic, touching at a
/// vertex, in the plane of a face (or a few ULPs off it), inside or spanning the box, or with an
/// edge through two boundary points.
Triangle triangle_near_box(ValueSource& values, const Aabb& box);
/// The box collapsed to a point (its lo corner) or to a segment along axis k: zero extent on
/// every axis but k; returns k, or -1 for a point.
int collapse(ValueSource& values, Aabb& box);
/// A triangle in a tilted plane through a point or segment box (axis k, or -1 for a point): the
/// box lies inside it, on its boundary or outside it, in its plane (up to the rounding of the
/// vertices), where the Minkowski difference is flat and the 13 usual axes cannot separate.
Triangle triangle_through_flat_box(ValueSource& values, const Aabb& box, int k);
/// A triangle in the regimes of the triangle tests' bounds, of about the given size, about the
/// plane of the first two columns of `frame` (its first edge along the first column): a sliver of
/// aspect ratio up to 2^40, in that plane, tilted out of it by 2^-8 to 2^-52 (nearly coplanar,
/// nearly parallel edges), or at any angle; its vertices in any order.
Triangle triangle_in_regime(ValueSource& values, double size, const Mat3& frame);
/// The triangle moved by `by`.
Triangle translated(const Triangle& t, const Vec3& by);
/// The triangle's vertices in one of their six orders.
void shuffle_vertices(Choices& choices, Triangle& t);
/// The mean of the vertices.
Vec3 centroid(const Triangle& t);
/// The largest |(v - centroid) . w| over the vertices.
double triangle_reach_along(const Triangle& t, const Vec3& w);
/// A frame for a triangle against a box with the given axes: the box's own (a face's plane, an
/// edge's direction), nearly those, or any.
Mat3 frame_against(ValueSource& values, const Mat3& axes);
/// The direction to slide along: one of the axes given, or any, either way.
Vec3 along_an_axis_or_any(ValueSource& values, const Mat3& axes);

/// `t` slid from `center` along w to the target margin: the family of a bound-reaching case, the
/// other shape reaching `other_reach` along w from `center`; put(moved triangle) makes the case.
template <class In, class Put>
In slid_to_the_bound(ValueSource& v, const GenerateOptions& options, const Triangle& t, const Vec3& center,
                     double other_reach, const Vec3& w, Put put) {
  const Triangle start = translated(t, center - centroid(t));
  const auto placed = [&](double s) { return put(translated(start, s * w)); };
  const double contact = (other_reach + triangle_reach_along(t, w)) / dot(w, w);
  const double apart = 2 * contact + 1 / std::sqrt(dot(w, w));
  const double s = place_at([&placed](double x) -> Input { return placed(x); }, 0, apart,
                            draw_margin_target(v.choices()), options, contact);
  return placed(s);
}

}  // namespace cc::harness
