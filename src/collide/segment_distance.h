// The distance between two segments, with witness points (separation.h).
#pragma once

#include <algorithm>
#include <utility>

#include "collide/segment.h"
#include "collide/separation.h"
#include "collide/vec3.h"

namespace cc {

/// The distance between two closed segments (never negative: segments have no inside) and a
/// closest pair, on_a on a and on_b on b. Parallel segments: any closest pair. A point segment
/// (a == b) is a point.
///  - The bound is certified after the fact: the witnesses give an upper bound on the distance
///    (they are points of the segments), the gap between the segments' projections on the
///    witnesses' direction a lower bound (as for any direction); distance_error covers both
///    ends, so it is small where the witnesses are nearly closest, whatever the configuration.
///  - Domain: finite inputs of magnitude at most 2^500; outside it, NaN (separation.h).
///    point_error: 16u of the largest endpoint coordinate, plus the subnormal slack.
Separation distance_segment_segment(const Segment& a, const Segment& b);

/// The parameters (s on a, t on b, both in [0, 1]) of a nearly closest pair a.a + s (a.b - a.a),
/// b.a + t (b.b - b.a): the minimiser of their distance as computed in floating point. Parallel
/// segments: some pair on the flat part of the distance. A point segment takes 0. Nothing is
/// certified: distance_segment_segment certifies the pair it takes from here.
std::pair<double, double> closest_segment_parameters(const Segment& a, const Segment& b);

namespace detail {

/// closest_segment_parameters on the segments' differences da = a.b - a.a, db = b.b - b.a and
/// r = a.a - b.a, all three scaled by one power of two (products of four of them must neither
/// overflow nor, but for features far smaller than the largest, underflow), with
/// length2_a = da . da and length2_b = db . db. Its dot products sum in order (dot_in_order): only
/// the choice of a pair depends on them, and every caller certifies the pair it takes. Inline:
/// distance_triangle_triangle calls it for nine edge pairs that share their edges.
inline std::pair<double, double> closest_parameters(const Vec3& da, const Vec3& db, const Vec3& r, double length2_a,
                                                    double length2_b) {
  // The parameter of b's point nearest a's point at s, and of a's point nearest b's point at t,
  // each clamped to its segment (0 on a point segment).
  const auto on_b_nearest = [&](double s) {
    return length2_b > 0 ? std::clamp(dot_in_order(r + s * da, db) / length2_b, 0.0, 1.0) : 0.0;
  };
  const auto on_a_nearest = [&](double t) {
    return length2_a > 0 ? std::clamp(dot_in_order(t * db - r, da) / length2_a, 0.0, 1.0) : 0.0;
  };
  // The distance is a convex quadratic in (s, t). Its minimiser on the lines, s0 = ((r x db).n) /
  // n.n with n = da x db (0 for parallel or point segments, where every s is as good), is
  // clamped to a; then b's point nearest it, then a's point nearest that: in exact arithmetic,
  // the minimiser over the two segments. The cross products (Lagrange's identity) keep nearly
  // parallel segments accurate: n errs by u |da| |db| per component, where
  // |da|^2 |db|^2 - (da.db)^2 would err by u |da|^2 |db|^2 against the tiny |n|^2.
  const Vec3 n = cross(da, db);
  const double n2 = dot_in_order(n, n);
  const double s0 = n2 > 0 ? std::clamp(dot_in_order(n, cross(db, r)) / n2, 0.0, 1.0) : 0.0;
  const double t = on_b_nearest(s0);
  return {on_a_nearest(t), t};
}

}  // namespace detail

/// A certified lower bound on the distance between a and b from one direction: the gap between
/// their projections on it (b's least minus a's greatest) over its length, less its rounding
/// bound, and 0 where the projections overlap. Exact in the limit along the direction of a
/// closest pair; any other direction gives less. A zero or non-finite direction gives 0.
double segment_gap_along(const Segment& a, const Segment& b, const Vec3& direction);

}  // namespace cc
