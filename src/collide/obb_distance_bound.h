// The bounds of distance_obb_obb (obb_distance.h), term by term, and its probing overload.
#pragma once

#include "collide/fp.h"
#include "collide/obb.h"
#include "collide/record_sink.h"
#include "collide/separation.h"

namespace cc::bounds {

/// distance_obb_obb, with size S = |d|_1 + |a.half|_1 + |b.half|_1 (d = b.center - a.center, as
/// computed) and magnitude M the largest centre coordinate.
struct ObbDistanceBound {
  double size, magnitude;

  /// The overlap of the boxes' projections on a direction n scaled to |n| in [1, 2 sqrt 3]
  /// (ra + rb - |d.n|, each radius sum_k h_k |axis_k . n|) over |n|: each dot rounds 3u |n|,
  /// each radius 6u |n| of its half extents' 1-norm, d.n 4u |n| |d|_1, the difference 2u |n| S;
  /// the length and the quotient 3.6u of the quotient (at most S): 11.7u S.
  double evaluation() const { return 16 * fp::u * size + fp::subnormal_slack; }
  /// A face's axis is its box's axis, not the cross product of the other two: within 3 eta in
  /// direction, and the overlap is S-Lipschitz in the direction.
  double face_direction() const { return 8 * kObbOrthonormalTolerance * size; }
  /// An edge pair's axis a_i x b_j of computed length `length`, each component by Kahan's
  /// difference of products within 2u of its exact value (plus 2^-1074 per rounding, where one
  /// underflows): within 2u |c| + 2^-1070 of the exact cross product, its unit direction within
  /// 4u + 2^-1069 / |c| however nearly parallel the edges are; times S (the overlap is
  /// S-Lipschitz in the direction).
  static double cross_angle(double length) { return 5 * fp::u + 0x1p-1068 / length; }
  double cross_direction(double length) const { return size * cross_angle(length); }
  /// An edge pair's axis left out (where the sliver costs less than the direction's error: edges
  /// parallel to within about u S / h): its face of a - b is the parallelogram the two edges
  /// span, 2 min(h_i, h_j) sin(theta) wide, with sin(theta) within 4u of the computed length.
  static double sliver(double least_half, double length) { return 2.01 * least_half * (length + 4 * fp::u); }
  /// Each corner c + sum +-h_k axis_k rounds 7u (M + S) in length; a point of an edge 16u (M + S);
  /// the witnesses of a depth are the nearest pair of the features (triangles of corners within
  /// M + 2S, triangle_distance_bound.h: 32u of that) less the translation, 96u (M + S) in all.
  double point() const { return 96 * fp::u * (magnitude + size) + fp::subnormal_slack; }
};

/// A call of distance_obb_obb and its answer, as computed.
struct ObbSeparation {
  Obb a, b;
  Separation answer;
  ObbDistanceBound bound;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (obb_distance.h), recording the call and its bounds into
/// `records` (bound_records.h); the same answer, bit for bit.
Separation distance_obb_obb(const Obb& a, const Obb& b, bounds::Records& records);

}  // namespace cc
