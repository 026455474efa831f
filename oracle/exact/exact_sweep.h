// Boxes moving with constant velocities over a step [0, 1], in exact arithmetic: the times at
// which they share a point (a closed interval, possibly empty), for parallelepipeds (OBBs with
// their axes as given, orthonormal or not, flat or not) and for axis-aligned boxes.
#pragma once

#include <vector>

#include "collide/moving_box.h"
#include "oracle/exact/convex_sat.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

/// The times in [first, last] at which the boxes meet; empty (first > last) when they do not.
struct ExactWindow {
  Rational first = 0, last = 1;
  bool hit() const { return first <= last; }
  /// Keeps the times at which |p + t s| <= r (one candidate axis: the offset of the projected
  /// centres moves at the rate s, and r is the sum of the projected radii).
  void restrict(const Rational& p, const Rational& s, const Rational& r);
};

/// One candidate axis of a moving pair: the offset p + t s of the projected centres, the sum r
/// of the projected radii, and the axis's conditioning (see CandidateAxis).
struct MovingAxis {
  CandidateAxis axis;
  Rational p, s, r;
};

/// The candidate axes of two moving boxes (the boxes as the parallelepipeds their axes span),
/// complete for every time: see candidate_axes_for_any_offset.
std::vector<MovingAxis> moving_axes(const MovingObb& a, const MovingObb& b);

/// The times at which two moving boxes meet, with each axis's radius grown by `grow` times its
/// conditioning (0: the boxes themselves).
ExactWindow exact_sweep(const std::vector<MovingAxis>& axes, const Rational& grow = 0);

/// The same for axis-aligned boxes a, b with velocities va, vb.
ExactWindow exact_sweep(const Aabb& a, const Vec3& va, const Aabb& b, const Vec3& vb);

}  // namespace cc::exact
