#include "oracle/exact/distance_check.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "oracle/exact/exact_distance.h"

namespace cc::exact {

decltype(harness::ExactVerdict::check_distance) distance_check(Rational squared, SquaredDistanceTo to_a, SquaredDistanceTo to_b) {
  return [squared = std::move(squared), to_a = std::move(to_a), to_b = std::move(to_b)](
             double distance, const Vec3& on_a, const Vec3& on_b, double distance_tolerance,
             double point_tolerance) -> std::optional<std::string> {
    std::ostringstream s;
    s.precision(17);
    for (double x : {distance, on_a.x, on_a.y, on_a.z, on_b.x, on_b.y, on_b.z}) {
      if (!std::isfinite(x)) {
        s << "gives a number that is not finite (" << x << ')';
        return s.str();
      }
    }
    if (!(distance_tolerance >= 0 && point_tolerance >= 0)) {
      s << "gives error bounds that are not numbers >= 0 (" << distance_tolerance << ", " << point_tolerance << ')';
      return s.str();
    }
    const Rational d = rational(distance), ed = rational(distance_tolerance), ep = rational(point_tolerance);
    if (!root_within(squared, d, ed)) {
      s << "distance " << distance << ", exact " << root_of(squared);
      return s.str();
    }
    const QVec3 a = rational(on_a), b = rational(on_b);
    for (const auto& [name, gap] : {std::pair{"on_a", to_a(a)}, std::pair{"on_b", to_b(b)}}) {
      if (gap > ep * ep) {
        s << name << " lies " << root_of(gap) << " from its shape";
        return s.str();
      }
    }
    const QVec3 w = b - a;
    if (!root_within(dot(w, w), d, ed + 2 * ep)) {
      s << "the points lie " << root_of(dot(w, w)) << " apart, the distance says " << distance;
      return s.str();
    }
    return std::nullopt;
  };
}

double root_of(const Rational& squared) { return sqrt(Magnitude::of(squared)).to_double(); }

}  // namespace cc::exact
