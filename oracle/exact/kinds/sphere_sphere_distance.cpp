// sphere_sphere_distance in exact arithmetic: the signed distance |c_b - c_a| - r_a - r_b, held as
// the square |c_b - c_a|^2 and the reach r_a + r_b (distance_check.h), so no root is rounded; an
// answer's points are checked on the balls' spheres. Whether the balls meet is decided on the
// same squares.
#include <algorithm>
#include <cstdio>

#include "harness/kinds/sphere_sphere.h"
#include "oracle/exact/distance_check.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {

template <>
ExactVerdict judge(const harness::SphereSphereInput& in);
template <>
harness::Explanation explain(const harness::SphereSphereInput& in);

namespace {

// The library's domain for distances: finite, of magnitude at most 2^500, radii >= 0.
constexpr int kDistanceMaxExponent = 500;

ExactSignedDistance signed_distance(const harness::SphereSphereDistanceInput& in) {
  const QVec3 d = rational(in.b.center) - rational(in.a.center);
  return {dot(d, d), 1, rational(in.a.radius) + rational(in.b.radius)};
}

}  // namespace

template <>
ExactVerdict judge(const harness::SphereSphereDistanceInput& in) {
  const Sphere &a = in.a, &b = in.b;
  // The two-ball test's documented answers (NaN or infinite input, a negative radius) are the
  // distance's too; its range is not ([2^-500, 2^500]: distances reach down to 0).
  ExactVerdict balls = judge(harness::SphereSphereInput{a, b});
  if (balls.contract == harness::Contract::documented) return balls;
  const double magnitude =
      max_magnitude({a.center.x, a.center.y, a.center.z, a.radius, b.center.x, b.center.y, b.center.z, b.radius});
  ExactVerdict v = distance_verdict(signed_distance(in), magnitude, boundary_of(a), boundary_of(b));
  if (auto why = scale_outside(magnitude, -1074, kDistanceMaxExponent)) return beyond_range(std::move(v), *why);
  return v;
}

template <>
harness::Explanation explain(const harness::SphereSphereDistanceInput& in) {
  harness::Explanation e = explain(harness::SphereSphereInput{in.a, in.b});
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", rounded_down(signed_distance(in)));
  e.facts.emplace_back("exact signed distance (rounded down)", text);
  return e;
}

}  // namespace cc::exact
