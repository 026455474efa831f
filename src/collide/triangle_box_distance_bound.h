// The bounds of distance_triangle_obb (triangle_box_distance.h), term by term, and its probing
// overload.
#pragma once

#include "collide/fp.h"
#include "collide/obb.h"
#include "collide/record_sink.h"
#include "collide/separation.h"
#include "collide/triangle.h"

namespace cc::bounds {

/// distance_triangle_obb, with size S = max_i |w_i|_1 + |box.half|_1 (w_i = v_i - box.center, as
/// computed) and magnitude M the largest vertex or centre coordinate.
struct TriangleBoxDistanceBound {
  double size, magnitude;

  /// The overlap of the projections on a direction n scaled to |n| in [1, 2 sqrt 3]: the box's
  /// [-r, r] (r = sum_k h_k |axis_k . n|) against the triangle's [min w_i . n, max w_i . n], over
  /// |n|. Each w_i rounds u |w_i| per coordinate (u |n| S on its projection), each dot 3u |n| S,
  /// the radius 6u |n| S, the sum or difference u |n| S; the length and the quotient 3.6u of the
  /// quotient (at most S): 14.6u S.
  double evaluation() const { return 20 * fp::u * size + fp::subnormal_slack; }
  /// A face's axis is its box's axis, not the cross product of the other two: within 3 eta in
  /// direction, and the overlap is S-Lipschitz in the direction.
  double face_direction() const { return 8 * kObbOrthonormalTolerance * size; }
  /// The triangle's normal, E1 x E2 of its exact edges (each scaled to a largest component in
  /// [1, 2), accurate_cross.h) of computed length `length`: each component within 3u of the
  /// exact one plus 8u^2 |E1|_inf |E2|_inf <= 32u^2 and underflow's 2^-1072, so its unit
  /// direction within 6u + (112u^2 + 2^-1069) / length, however thin the triangle is.
  static double normal_angle(double length) { return 8 * fp::u + (128 * fp::u * fp::u + 0x1p-1068) / length; }
  /// An edge pair's axis E x a_k (E a triangle's exact edge scaled as above, a_k a box axis, the
  /// box's edge exactly) of computed length `length`: each component within 3u plus 8u^2 and
  /// underflow's 2^-1072, its unit direction within 6u + (28u^2 + 2^-1069) / length.
  static double edge_angle(double length) { return 8 * fp::u + (32 * fp::u * fp::u + 0x1p-1068) / length; }
  /// What a direction `angle` off its exact normal may cost the overlap.
  double direction(double angle) const { return size * angle; }
  /// An edge pair's axis left out (a triangle edge and a box axis parallel to within about
  /// u S / h): its face of the difference is the parallelogram the two edges span, its width the
  /// shorter one's length times sin(theta), sin(theta) within 8u of `sine` (the computed
  /// |E x a_k| / |E|), `least_half` half the shorter one's length.
  static double sliver(double least_half, double sine) { return 2.01 * least_half * (sine + 8 * fp::u); }
  /// Each box corner c + sum +-h_k axis_k rounds 7u (M + S), a point of an edge or of the box
  /// clamped 16u (M + S), a foot on the triangle 32u M; the witnesses of a depth are the nearest
  /// pair of the features (triangles of points within M + 2S, triangle_distance_bound.h: 32u of
  /// that) less the translation: 96u (M + S) in all.
  double point() const { return 96 * fp::u * (magnitude + size) + fp::subnormal_slack; }
};

/// A call of distance_triangle_obb and its answer, as computed.
struct TriangleBoxSeparation {
  Triangle triangle;
  Obb box;
  Separation answer;
  TriangleBoxDistanceBound bound;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (triangle_box_distance.h), recording the call and its bounds
/// into `records` (bound_records.h); the same answer, bit for bit.
Separation distance_triangle_obb(const Triangle& t, const Obb& box, bounds::Records& records);

}  // namespace cc
