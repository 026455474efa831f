#include "collide/projection_gap.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "collide/fp.h"
#include "collide/length.h"

namespace cc {

double projection_gap(std::span<const Vec3> a, std::span<const Vec3> b, const Vec3& direction) {
  // Measured from a's first point, with the direction scaled so that its largest component m
  // is in [1, 2) (so its length is at least m), and R the largest offset's 1-norm: each offset
  // rounds u and its dot 3u, 4u m R each over the length, 8u R for the two sides; their
  // difference u of 2mR, 2u R; the division and the length 3.6u of the gap (at most 2R):
  // 17.2u R.
  if (a.empty() || b.empty()) return 0;
  const Vec3 unit = unit_scaled(direction);  // a direction only: no underflow in its products
  const double scale = length(unit);
  if (!(scale > 0) || !std::isfinite(scale)) return 0;
  constexpr double inf = std::numeric_limits<double>::infinity();
  double reach = 0, high_a = -inf, low_b = inf;
  for (const Vec3& p : a) {
    const Vec3 offset = p - a[0];
    reach = std::max(reach, norm1(offset));
    high_a = std::max(high_a, dot(unit, offset));
  }
  for (const Vec3& p : b) {
    const Vec3 offset = p - a[0];
    reach = std::max(reach, norm1(offset));
    low_b = std::min(low_b, dot(unit, offset));
  }
  return std::max(0.0, (low_b - high_a) / scale - 24 * fp::u * reach - fp::subnormal_slack);
}

}  // namespace cc
