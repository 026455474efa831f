#include "collide/segment_distance.h"

#include <algorithm>
#include <cmath>

#include "collide/fp.h"
#include "collide/length.h"
#include "collide/projection_gap.h"

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
  return detail::closest_parameters(da, db, r, dot_in_order(da, da), dot_in_order(db, db));
}

double segment_gap_along(const Segment& a, const Segment& b, const Vec3& direction) {
  const Vec3 ends_a[2] = {a.a, a.b}, ends_b[2] = {b.a, b.b};
  return projection_gap(ends_a, ends_b, direction);
}

Separation distance_segment_segment(const Segment& a, const Segment& b) {
  if (!finite(a) || !finite(b)) return Separation::outside_the_domain();
  const auto [s, t] = closest_segment_parameters(a, b);
  const Vec3 on_a = a.a + s * (a.b - a.a), on_b = b.a + t * (b.b - b.a);
  // Each witness, per coordinate with M the largest endpoint coordinate: the difference of the
  // ends rounds u of 2M, the product u of 2M and carries the difference's error (2uM), the sum u
  // of 3M: 7uM, 12.2uM in length.
  const double magnitude = std::max({max_abs(a.a), max_abs(a.b), max_abs(b.a), max_abs(b.b)});
  const double point_error = 16 * fp::u * magnitude + fp::subnormal_slack;
  // The lower end: the gap along the witnesses' direction, and along the segments' common
  // normal, which a noisy pair of witnesses (nearly touching segments, where their rounding
  // turns their direction) does not tilt. Both face from a to b; none when the witnesses meet.
  const Vec3 along = on_b - on_a;
  double lower = 0;
  if (along != Vec3{}) {
    Vec3 normal = unit_scaled(cross(a.b - a.a, b.b - b.a));
    if (dot(normal, along) < 0) normal = -1.0 * normal;
    lower = std::max(segment_gap_along(a, b, along), segment_gap_along(a, b, normal));
  }
  return Separation::certified(on_a, on_b, point_error, lower);
}

}  // namespace cc
