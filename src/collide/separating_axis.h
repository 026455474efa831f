// Certified separating-axis tests shared by the triangle queries (an internal header).
//
// Any direction is a valid candidate axis: if the projections of two convex sets onto it are
// disjoint, so are the sets. So an axis may be computed with rounding errors; only the
// projections onto the axis as computed need an error bound, and an axis separates only when
// the gap between the projected intervals exceeds that bound.
#pragma once

#include <span>

#include "collide/aabb.h"
#include "collide/record_sink.h"
#include "collide/sat_bound.h"
#include "collide/triangle.h"

namespace cc::sat {

/// A closed interval of projections.
struct Interval {
  double lo, hi;
};

/// The vertices of a triangle as a convex set to project.
struct TriangleSet {
  explicit TriangleSet(const Triangle& tri);
  const Triangle& t;
  double magnitude() const { return magnitude_; }  // largest absolute coordinate
  Interval project(const Vec3& axis) const;  // each end within 3u |axis|_1 magnitude()
  Vec3 centroid() const;

 private:
  double magnitude_;  // computed once: every candidate axis needs it
};

/// An axis-aligned box as a convex set to project.
struct BoxSet {
  explicit BoxSet(const Aabb& b);
  const Aabb& box;
  double magnitude() const { return magnitude_; }
  Interval project(const Vec3& axis) const;
  Vec3 centroid() const;

 private:
  double magnitude_;
};

/// True when the projections of a and b onto `axis` are apart by more than their rounding
/// error (bounds::SatBound), with both sets' coordinates also allowed to be off by
/// `perturbation` (a bound on errors made before, such as a change of frame). Records the gap
/// (bounds::SatAxis) into `records` (bounds::NoRecords or bounds::RecordsRef).
template <class A, class B, class Records>
bool separates(const Vec3& axis, const A& a, const B& b, double perturbation, Records& records);

/// The candidate axes that the usual face and edge axes lack when the Minkowski difference of
/// a and b is not full-dimensional (coplanar or degenerate shapes): for the edge directions
/// `generators` of both sets, every cross product c of two of them, every c x g, every g,
/// every g x (g x o) and o, where o joins the centroids. With these the test is complete for
/// flat, collinear and single-point configurations. True when one of them separates.
template <class A, class B, class Records>
bool separated_by_degenerate_axes(const A& a, const B& b, std::span<const Vec3> generators,
                                  double perturbation, Records& records);

}  // namespace cc::sat
