#include "collide/segment_distance.h"

#include <algorithm>
#include <cmath>

#include "collide/fp.h"
#include "collide/length.h"

namespace cc {

// The parameters do not change with scale, so the differences are scaled by one power of two
// that brings the largest coordinate into [1, 2): the products of four of them neither overflow
// nor underflow.
std::pair<double, double> closest_segment_parameters(const Segment& a, const Segment& b) {
  Vec3 da = a.b - a.a, db = b.b - b.a, r = a.a - b.a;
  const double m = std::max({max_abs(da), max_abs(db), max_abs(r)});
  if (m > 0) {
    const int e = fp::exponent_of(m);
    da = scaled(da, e), db = scaled(db, e), r = scaled(r, e);
  }
  const double aa = dot(da, da), bb = dot(db, db), f = dot(db, r);
  if (aa == 0 && bb == 0) return {0, 0};
  if (aa == 0) return {0, std::clamp(f / bb, 0.0, 1.0)};
  const double c = dot(da, r);
  if (bb == 0) return {std::clamp(-c / aa, 0.0, 1.0), 0};
  const double ab = dot(da, db);
  // The unclamped s is ((da.db)(db.r) - (da.r)(db.db)) / (|da|^2 |db|^2 - (da.db)^2), written
  // with cross products (Lagrange's identity), whose cancellation is far milder where the
  // segments are nearly parallel: n = da x db errs by u |da| |db| per component, where the
  // difference of products would err by u |da|^2 |db|^2 against the tiny |n|^2.
  const Vec3 n = cross(da, db);
  const double denom = dot(n, n);
  double s = denom > 0 ? std::clamp(dot(n, cross(db, r)) / denom, 0.0, 1.0) : 0.0;
  double t = (ab * s + f) / bb;
  if (t < 0) {
    t = 0, s = std::clamp(-c / aa, 0.0, 1.0);
  } else if (t > 1) {
    t = 1, s = std::clamp((ab - c) / aa, 0.0, 1.0);
  }
  return {s, t};
}

double segment_gap_along(const Segment& a, const Segment& b, const Vec3& direction) {
  // Measured from a.a, with the direction scaled so that its largest component m is in [1, 2)
  // (so its length is at least m), and R the largest offset's 1-norm: each offset rounds u and
  // its dot 3u, 4u m R each over the length, 8u R for the two sides; their difference u of 2mR,
  // 2u R; the division and the length 3.6u of the gap (at most 2R): 17.2u R.
  const Vec3 unit = unit_scaled(direction);  // a direction only: no underflow in its products
  const double scale = length(unit);
  if (!(scale > 0) || !std::isfinite(scale)) return 0;
  const Vec3 ends[4] = {Vec3{}, a.b - a.a, b.a - a.a, b.b - a.a};
  double reach = 0;
  for (const Vec3& e : ends) reach = std::max(reach, norm1(e));
  const double high_a = std::max(dot(unit, ends[0]), dot(unit, ends[1]));
  const double low_b = std::min(dot(unit, ends[2]), dot(unit, ends[3]));
  return std::max(0.0, (low_b - high_a) / scale - 24 * fp::u * reach - fp::subnormal_slack);
}

Separation distance_segment_segment(const Segment& a, const Segment& b) {
  if (!finite(a.a) || !finite(a.b) || !finite(b.a) || !finite(b.b)) return Separation::outside_the_domain();
  const auto [s, t] = closest_segment_parameters(a, b);
  const Vec3 on_a = a.a + s * (a.b - a.a), on_b = b.a + t * (b.b - b.a);
  // Each witness, per coordinate with M the largest endpoint coordinate: the difference of the
  // ends rounds u of 2M, the product u of 2M and carries the difference's error (2uM), the sum u
  // of 3M: 7uM, 12.2uM in length.
  const double magnitude = std::max({max_abs(a.a), max_abs(a.b), max_abs(b.a), max_abs(b.b)});
  const double point_error = 16 * fp::u * magnitude + fp::subnormal_slack;
  const Vec3 n = on_b - on_a;
  const double d = length(n);
  // Upper end: the exact witnesses are points of the segments, within point_error of these;
  // their distance is within 2 point_error and the length's rounding (u for n, 2.6u) of d.
  const double upper = d + 2 * point_error + 4 * fp::u * d;
  // Lower end: the gap along the witnesses' direction (none when they coincide).
  const double lower = d > 0 ? segment_gap_along(a, b, n) : 0;
  return {d, on_a, on_b, std::max(upper - d, d - lower), point_error};
}

}  // namespace cc
