// The answer of a distance query: how far apart two shapes are, signed, and a pair of points that
// realises it, each with a certified bound on its error.
#pragma once

#include <algorithm>
#include <limits>

#include "collide/fp.h"
#include "collide/length.h"
#include "collide/vec3.h"

namespace cc {

/// The signed distance between two closed shapes a and b, and a pair of witness points.
///  - distance > 0: the shapes are apart by that much (the length of the shortest segment
///    between them); distance < 0: they overlap, and -distance is the penetration depth (the
///    length of the shortest translation of b that separates them); 0: they touch.
///  - on_a, on_b: when apart, a pair of points of the shapes whose distance is the answer (a
///    closest pair, or as near one as the bounds say); when they overlap, a point of a's
///    boundary and a point of b's with on_a - on_b the shortest separating translation of b.
///    Where closest pairs are not unique, any of them.
///  - |distance - the exact signed distance| <= distance_error, and each witness lies within
///    point_error of its shape (of its boundary where they overlap), so
///    | |on_b - on_a| - |exact| | <= 2 point_error + distance_error. Both bounds are certified
///    for inputs in the query's domain.
///  - Outside the domain (NaN or infinite input, a negative radius or half extent): distance
///    NaN, the points NaN, both errors infinite.
struct Separation {
  double distance = 0;
  Vec3 on_a, on_b;
  double distance_error = 0;
  double point_error = 0;

  /// The answer certified after the fact for shapes that do not overlap (distance >= 0), from
  /// witnesses within point_error of their shapes and a lower bound on the distance (a gap
  /// along some direction, projection_gap.h): the witnesses' distance, with the error that
  /// covers both the upper end (their distance, their rounding, and that of the length: u for
  /// the difference and 2.6u) and the lower one.
  static Separation certified(const Vec3& on_a, const Vec3& on_b, double point_error, double lower) {
    const double d = length(on_b - on_a);
    const double upper = fp::sum3(d, 2 * point_error, 4 * fp::u * d);
    return {d, on_a, on_b, std::max(upper - d, d - lower), point_error};
  }

  /// certified(on_a, on_b, point_error, lower) with the lower bound asked for only where the
  /// answer depends on it: `lower(enough)` gives it (at least 0), and may stop early at a bound
  /// `g` for which enough(g) holds, as every bound at least g gives the same answer. The same
  /// bits as certified() with the bound lower() would give in full.
  template <class LowerBound>
  static Separation certified_lazily(const Vec3& on_a, const Vec3& on_b, double point_error, LowerBound&& lower) {
    const double d = length(on_b - on_a);
    const double above = fp::sum3(d, 2 * point_error, 4 * fp::u * d) - d;
    // A lower bound g >= 0 leaves the error at `above` when d - g <= above, and so does every
    // larger one; with d <= above, every one does.
    const auto enough = [d, above](double g) { return d - g <= above; };
    return {d, on_a, on_b, d <= above ? above : std::max(above, d - lower(enough)), point_error};
  }

  /// The answer outside a query's domain: NaN distance and points, infinite errors.
  static Separation outside_the_domain() {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    return {nan, {nan, nan, nan}, {nan, nan, nan}, inf, inf};
  }
};

}  // namespace cc
