// The exact check of a distance query's answer (ExactVerdict::check_distance), for any two shapes
// given by their exact squared distance and the exact squared distance from a point to each.
#pragma once

#include <cmath>
#include <functional>
#include <limits>

#include "harness/model/oracle.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

/// The squared distance from a point to one shape, exact.
using SquaredDistanceTo = std::function<Rational(const QVec3& point)>;

/// check_distance for shapes a and b at squared distance `squared`: an answer (distance, on_a,
/// on_b) is right when |distance - sqrt(squared)| <= distance_tolerance, on_a and on_b lie within
/// point_tolerance of a and b, and | |on_b - on_a| - distance | <= distance_tolerance + 2
/// point_tolerance, each decided on squares. A NaN or negative tolerance, or a non-finite number
/// in the answer, is wrong.
decltype(harness::ExactVerdict::check_distance) distance_check(Rational squared, SquaredDistanceTo to_a, SquaredDistanceTo to_b);

/// The distance of a squared one, rounded (for reports; judging uses the squares).
double root_of(const Rational& squared);

/// The largest double whose square is at most `squared` (>= 0): the distance rounded down,
/// exactly (the largest finite double beyond the doubles). For any exact number type that
/// compares and multiplies with doubles exactly (Rational, CGAL's exact FT), `to_double`
/// rounding one to a double: an estimate from the square brought into the doubles' normal range
/// by exact powers of 4, then nudged by ulps.
template <class Number, class ToDouble>
double root_down(const Number& squared, ToDouble to_double) {
  if (squared <= 0) return 0;
  Number scaled = squared;
  int half_exponent = 0;
  for (; scaled < Number(0x1p-600); half_exponent -= 100) scaled = scaled * Number(0x1p200);
  for (; scaled > Number(0x1p600); half_exponent += 100) scaled = scaled * Number(0x1p-200);
  double d = std::ldexp(std::sqrt(to_double(scaled)), half_exponent);
  if (!(d < INFINITY)) d = std::numeric_limits<double>::max();
  const auto at_most = [&squared](double x) { return Number(x) * Number(x) <= squared; };
  while (d > 0 && !at_most(d)) d = std::nextafter(d, 0.0);
  while (d < std::numeric_limits<double>::max() && at_most(std::nextafter(d, INFINITY))) d = std::nextafter(d, INFINITY);
  return d;
}
inline double root_down(const Rational& squared) {
  return root_down(squared, [](const Rational& q) { return to_double(q); });
}

}  // namespace cc::exact
