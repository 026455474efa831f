// The nearest of candidate pairs of points, compared on their differences scaled by a power of
// two (so that the squares neither overflow nor, but for pairs far nearer than the scale,
// underflow).
#pragma once

#include <limits>

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
    const double sq = dot(v, v);
    if (sq < square) on_a = p, on_b = q, square = sq;
  }
};

}  // namespace cc
