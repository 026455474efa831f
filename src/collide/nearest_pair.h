// The nearest of candidate pairs of points, compared on their differences scaled by a power of
// two (so that the squares neither overflow nor, but for pairs far nearer than the scale,
// underflow).
#pragma once

#include <limits>

#include "collide/fp.h"
#include "collide/length.h"
#include "collide/vec3.h"

namespace cc {

/// The nearest pair kept so far and its squared distance on differences scaled by 2^-exponent
/// (+infinity before any). Only which pair is kept depends on the scaling and its rounding.
struct NearestPair {
  int exponent = 0;
  Vec3 on_a, on_b;
  double square = std::numeric_limits<double>::infinity();

  /// Keeps (p, q) when nearer than every pair before it.
  void keep_nearer(const Vec3& p, const Vec3& q) {
    const Vec3 v = scaled(q - p, exponent);
    const double sq = dot_in_order(v, v);
    if (sq < square) on_a = p, on_b = q, square = sq;
  }

  /// Whether features whose squared gap (scaled the same way) is `square_gap` may hold a pair
  /// nearer than this one, up to rounding. For pruning only.
  bool may_improve_on(double square_gap) const { return square_gap <= square * (1 + 0x1p-20); }

  /// Whether `gap`, a certified lower bound on the distance (unscaled), shows this pair nearest to
  /// within 2^-40 of its distance: then no other candidate need be tried.
  bool proven_by(double gap) const {
    const double g = fp::scale2(gap, -exponent);
    return g * g >= square * (1 - 0x1p-40);
  }
};

}  // namespace cc
