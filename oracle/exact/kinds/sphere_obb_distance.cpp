// sphere_obb_distance in exact arithmetic: the box is the parallelepiped its axes span, as given.
// A centre outside the box: the signed distance is its distance to the box less the radius; a
// centre in it (its boundary included): minus its distance to the boundary (the nearest face's
// plane) less the radius. Each held as a square and the radius (distance_check.h), so no root is
// rounded; an answer's points are checked on the ball's sphere and on the box's faces.
#include <algorithm>

#include "oracle/exact/distance_check.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/exact_distance.h"
#include "oracle/exact/exact_polytopes.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {
namespace {

// The library's domain for distances: finite, of magnitude at most 2^500.
constexpr int kDistanceMaxExponent = 500;

ExactSignedDistance signed_distance(const harness::SphereObbDistanceInput& in) {
  const QVec3 c = rational(in.ball.center);
  if (in_box(c, in.box)) return {squared_depth_in_box(c, in.box), -1, rational(in.ball.radius)};
  return {squared_distance_to_box(c, in.box), 1, rational(in.ball.radius)};
}

}  // namespace

template <>
ExactVerdict judge(const harness::SphereObbDistanceInput& in) {
  const Sphere& s = in.ball;
  if (!all_finite({s.center.x, s.center.y, s.center.z, s.radius})) return documented(false, "NaN or infinite input");
  if (auto out = obb_outside_domain(in.box)) return *out;
  if (s.radius < 0) return documented(false, "negative radius");
  if (auto why = not_orthonormal(in.box.axes)) return unspecified(*why);
  const double magnitude = std::max(max_magnitude({s.center.x, s.center.y, s.center.z, s.radius}), magnitude_of(in.box));
  ExactVerdict v = distance_verdict(signed_distance(in), magnitude, boundary_of(s), boundary_of(in.box));
  if (auto why = scale_outside(magnitude, -1074, kDistanceMaxExponent)) return beyond_range(std::move(v), *why);
  return v;
}

template <>
harness::Explanation explain(const harness::SphereObbDistanceInput& in) {
  harness::Explanation e;
  const ExactSignedDistance d = signed_distance(in);
  e.title = "distances";
  e.facts = {{"the ball's centre", d.sign < 0 ? "in the box" : "outside the box"},
             {d.sign < 0 ? "its distance to the box's boundary" : "its distance to the box", num(root_of(d.squared))},
             {"radius", num(in.ball.radius)},
             {"exact signed distance (rounded down)", num(rounded_down(d))}};
  e.deciding = d.sign < 0 ? "the centre's squared depth plus radius^2" : "radius^2 - the centre's squared distance to the box";
  const Rational deciding = d.sign < 0 ? Rational(d.squared + d.reach * d.reach) : Rational(d.reach * d.reach - d.squared);
  e.deciding_value = to_double(deciding);
  e.deciding_ulps = in_ulps(e.deciding_value, std::max(to_double(d.reach * d.reach), to_double(d.squared)));
  return e;
}

}  // namespace cc::exact
