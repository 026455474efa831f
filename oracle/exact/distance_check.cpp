#include "oracle/exact/distance_check.h"

#include <cmath>
#include <limits>
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

double root_down(const Rational& squared) {
  if (squared <= 0) return 0;
  // An estimate from the square brought into the doubles' normal range by powers of 4 (exact),
  // then nudged by ulps.
  Rational scaled = squared;
  int half_exponent = 0;
  for (; scaled < rational(0x1p-600); half_exponent -= 100) scaled *= rational(0x1p200);
  for (; scaled > rational(0x1p600); half_exponent += 100) scaled *= rational(0x1p-200);
  double d = std::ldexp(std::sqrt(to_double(scaled)), half_exponent);
  if (!(d < INFINITY)) d = std::numeric_limits<double>::max();
  const auto at_most = [&squared](double x) { return rational(x) * rational(x) <= squared; };
  while (d > 0 && !at_most(d)) d = std::nextafter(d, 0.0);
  while (d < std::numeric_limits<double>::max() && at_most(std::nextafter(d, INFINITY))) d = std::nextafter(d, INFINITY);
  return d;
}

}  // namespace cc::exact
