// A certified lower bound on the distance between two convex hulls of points, from one
// direction: the gap between their projections on it.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "collide/fp.h"
#include "collide/length.h"
#include "collide/vec3.h"

namespace cc {

/// The gap between the projections of a's points and b's points on `direction` (b's least
/// minus a's greatest) over its length, less its rounding bound; 0 where the projections
/// overlap. For any direction it is at most the distance between the hulls of a and b, and it
/// is the distance, but for the rounding bound, along the direction of a closest pair. A zero
/// or non-finite direction, or an empty list, gives 0. Finite points of magnitude at most 2^500.
/// Inline: a distance query certifies its answer with one or two of these on the same points.
inline double projection_gap(std::span<const Vec3> a, std::span<const Vec3> b, const Vec3& direction) {
  // Measured from a's first point, with the direction scaled so that its largest component m
  // is in [1, 2) (so its length is at least m), and R the largest offset's 1-norm: each offset
  // rounds u and its dot 3u (in any order of summation), 4u m R each over the length, 8u R for
  // the two sides; their difference u of 2mR, 2u R; the division and the length 3.6u of the gap
  // (at most 2R): 17.2u R. The sums are taken left to right (faster than fp::sum3, and the bound
  // holds for any order; the gap then follows the axes' order only within it).
  if (a.empty() || b.empty()) return 0;
  const Vec3 unit = unit_scaled(direction);  // a direction only: no underflow in its products
  const auto along = [&unit](const Vec3& v) { return dot_in_order(unit, v); };
  const double scale = std::sqrt(along(unit));  // within 2u (the 3.6u below counts 2.6u)
  if (!(scale > 0) || !std::isfinite(scale)) return 0;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const auto norm1 = [](const Vec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); };
  double reach = 0, high_a = -inf, low_b = inf;
  for (const Vec3& p : a) {
    const Vec3 offset = p - a[0];
    reach = std::max(reach, norm1(offset));
    high_a = std::max(high_a, along(offset));
  }
  for (const Vec3& p : b) {
    const Vec3 offset = p - a[0];
    reach = std::max(reach, norm1(offset));
    low_b = std::min(low_b, along(offset));
  }
  return std::max(0.0, (low_b - high_a) / scale - 24 * fp::u * reach - fp::subnormal_slack);
}

}  // namespace cc
