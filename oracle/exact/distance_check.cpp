#include "oracle/exact/distance_check.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "oracle/exact/domain.h"
#include "oracle/exact/exact_distance.h"

namespace cc::exact {

NearBoundary boundary_of(const Triangle& triangle) {
  return [triangle](const QVec3& p, const Rational& e) { return squared_distance_to_triangle(p, triangle) <= e * e; };
}

NearBoundary boundary_of(const Sphere& ball) {
  return [c = rational(ball.center), r = rational(ball.radius)](const QVec3& p, const Rational& e) {
    const QVec3 d = p - c;
    return root_within(dot(d, d), r, e);
  };
}

NearBoundary boundary_of(const Obb& box) {
  return [box](const QVec3& p, const Rational& e) {
    return (in_box(p, box) ? squared_depth_in_box(p, box) : squared_distance_to_box(p, box)) <= e * e;
  };
}

decltype(harness::ExactVerdict::check_distance) distance_check(ExactSignedDistance exact, NearBoundary a, NearBoundary b) {
  return [exact = std::move(exact), a = std::move(a), b = std::move(b)](const harness::DistanceClaim& claim) -> std::optional<std::string> {
    std::ostringstream s;
    s.precision(17);
    const Vec3 &on_a = claim.on_a, &on_b = claim.on_b;
    for (double x : {claim.distance, on_a.x, on_a.y, on_a.z, on_b.x, on_b.y, on_b.z}) {
      if (!std::isfinite(x)) {
        s << "gives a number that is not finite (" << x << ')';
        return s.str();
      }
    }
    if (!(claim.distance_tolerance >= 0 && claim.point_tolerance >= 0)) {
      s << "gives error bounds that are not numbers >= 0 (" << claim.distance_tolerance << ", " << claim.point_tolerance << ')';
      return s.str();
    }
    const Rational d = rational(claim.distance), ed = rational(claim.distance_tolerance), ep = rational(claim.point_tolerance);
    // distance = sign sqrt(squared) - reach, within ed: sqrt(squared) = sign (distance + reach).
    if (!root_within(exact.squared, exact.sign * (d + exact.reach), ed)) {
      s << "distance " << claim.distance << ", exact " << rounded_down(exact);
      return s.str();
    }
    if (!claim.witnessed) return std::nullopt;
    const QVec3 pa = rational(on_a), pb = rational(on_b);
    for (const auto& [name, near] : {std::pair{"on_a", a(pa, ep)}, std::pair{"on_b", b(pb, ep)}}) {
      if (!near) {
        s << name << " lies farther than " << claim.point_tolerance << " from its shape's boundary";
        return s.str();
      }
    }
    const QVec3 w = pb - pa;
    if (!root_within(dot(w, w), abs(d), ed + 2 * ep)) {
      s << "the points lie " << root_of(dot(w, w)) << " apart, the distance says " << claim.distance;
      return s.str();
    }
    return std::nullopt;
  };
}

int overlap_sign(const ExactSignedDistance& exact) {
  // -(sign sqrt(squared) - reach): sqrt(squared) + reach inside, reach - sqrt(squared) outside.
  if (exact.sign < 0) return sgn(exact.squared) + sgn(exact.reach) > 0 ? 1 : 0;
  const int of_squares = sgn(exact.reach * exact.reach - exact.squared);
  return sgn(exact.reach) < 0 ? -1 : of_squares;
}

harness::ExactVerdict distance_verdict(const ExactSignedDistance& exact, double magnitude, NearBoundary a, NearBoundary b) {
  harness::ExactVerdict v;
  const int overlap = overlap_sign(exact);
  const double distance = rounded_down(exact);
  v.answer.hit = overlap >= 0;
  v.answer.params = {distance};
  v.scale = scale_of(magnitude);
  v.margin = signed_margin(-distance / v.scale, overlap);
  v.check_distance = distance_check(exact, std::move(a), std::move(b));
  return v;
}

double rounded_down(const ExactSignedDistance& exact) {
  return signed_distance_down(exact.sign, exact.squared, exact.reach, [](const Rational& q) { return to_double(q); });
}

double root_of(const Rational& squared) { return sqrt(Magnitude::of(squared)).to_double(); }

}  // namespace cc::exact
