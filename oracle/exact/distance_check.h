// The exact check of a distance query's answer (ExactVerdict::check_distance), for any two shapes
// given by their exact signed distance and whether a point lies near each one's boundary.
#pragma once

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "collide/obb.h"
#include "collide/sphere.h"
#include "collide/triangle.h"
#include "harness/model/oracle.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

/// An exact signed distance as sign sqrt(squared) - reach: for two triangles the root of their
/// squared distance (sign +1, reach 0); for two balls the centres' distance less the radii's sum;
/// for a ball and a box the centre's distance to the box less the radius, or, for a centre inside
/// the box, minus its distance to the box's boundary less the radius (sign -1).
struct ExactSignedDistance {
  Rational squared;
  int sign = 1;
  Rational reach = 0;
};

/// Whether a point lies within a tolerance (>= 0) of a shape's boundary, exactly.
using NearBoundary = std::function<bool(const QVec3& point, const Rational& tolerance)>;

/// The boundary of a closed triangle (the triangle itself: it has no inside), of a ball (its
/// sphere), of a box (the parallelepiped its axes span, as given: its six faces).
NearBoundary boundary_of(const Triangle& triangle);
NearBoundary boundary_of(const Sphere& ball);
NearBoundary boundary_of(const Obb& box);

/// check_distance for shapes a and b at the exact signed distance `exact`: a claim is right when
/// |distance - exact| <= distance_tolerance and, where it gives points, on_a and on_b lie within
/// point_tolerance of a's and b's boundaries and | |on_b - on_a| - |distance| | <=
/// distance_tolerance + 2 point_tolerance, each decided on squares. A NaN or negative tolerance,
/// or a non-finite number in the claim, is wrong.
decltype(harness::ExactVerdict::check_distance) distance_check(ExactSignedDistance exact, NearBoundary a, NearBoundary b);

/// > 0 where the shapes overlap (the signed distance < 0), 0 where they touch, < 0 where they are
/// apart.
int overlap_sign(const ExactSignedDistance& exact);

/// The verdict of a distance query on shapes a and b whose coordinates reach `magnitude`: a hit
/// where they meet, the margin (minus the signed distance over the scale: > 0 overlapping, 0 only
/// touching), the distance rounded down as params, the scale and distance_check.
harness::ExactVerdict distance_verdict(const ExactSignedDistance& exact, double magnitude, NearBoundary a, NearBoundary b);

/// The exact signed distance rounded down (signed_distance_down below), for answers, reports and
/// the CGAL audit; judging uses the squares.
double rounded_down(const ExactSignedDistance& exact);

/// The distance of a squared one, rounded (for reports; judging uses the squares).
double root_of(const Rational& squared);

/// The largest finite double x with at_most(x), for a predicate true up to some value and false
/// beyond it (at_most(-max) assumed true): searched from `estimate` in steps doubling in ulps,
/// then by halving, so that a poor estimate costs some 130 calls, never a walk ulp by ulp.
template <class AtMost>
double largest_double_where(AtMost at_most, double estimate) {
  // The finite doubles in order as 0 (-max) ... 2 top (max), top the position of +0 = -0.
  constexpr std::uint64_t top = std::bit_cast<std::uint64_t>(DBL_MAX), end = 2 * top;
  const auto position = [](double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    return bits >> 63 ? top - (bits & ~(std::uint64_t{1} << 63)) : top + bits;
  };
  const auto value = [](std::uint64_t p) {
    return p >= top ? std::bit_cast<double>(p - top) : -std::bit_cast<double>(top - p);
  };
  const auto doubled = [](std::uint64_t step) { return step < (std::uint64_t{1} << 62) ? 2 * step : step; };
  const std::uint64_t start = position(std::isnan(estimate) ? 0.0 : std::clamp(estimate, -DBL_MAX, DBL_MAX));
  std::uint64_t lo = 0, hi = end + 1;  // at_most(value(lo)); hi past the answer (end + 1: past max)
  if (at_most(value(start))) {
    lo = start;
    for (std::uint64_t step = 1; step <= end - lo; step = doubled(step)) {
      if (!at_most(value(lo + step))) {
        hi = lo + step;
        break;
      }
      lo += step;
    }
  } else {
    hi = start;
    for (std::uint64_t step = 1; step <= hi; step = doubled(step)) {
      if (at_most(value(hi - step))) {
        lo = hi - step;
        break;
      }
      hi -= step;
    }
  }
  while (hi - lo > 1) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    (at_most(value(mid)) ? lo : hi) = mid;
  }
  return value(lo);
}

/// The signed distance sign sqrt(squared) - reach (squared >= 0) rounded down, exactly: the
/// largest double at most it (the largest finite double beyond the doubles). For any exact number
/// type that compares, adds and multiplies with doubles exactly (Rational, CGAL's exact FT),
/// `to_double` rounding one to a double. The estimate it starts from is the root of the square
/// brought into the doubles' normal range by exact powers of 4, less the reach.
template <class Number, class ToDouble>
double signed_distance_down(int sign, const Number& squared, const Number& reach, ToDouble to_double) {
  Number scaled = squared;
  int half_exponent = 0;
  for (; scaled > 0 && scaled < Number(0x1p-600); half_exponent -= 100) scaled = scaled * Number(0x1p200);
  for (; scaled > Number(0x1p600); half_exponent += 100) scaled = scaled * Number(0x1p-200);
  const double root = std::ldexp(std::sqrt(to_double(scaled)), half_exponent);
  const auto at_most = [&](double x) {
    // x <= sign sqrt(squared) - reach: x + reach <= sqrt(squared), or <= -sqrt(squared).
    const Number y = Number(x) + reach;
    return sign > 0 ? (y <= 0 || y * y <= squared) : (y <= 0 && y * y >= squared);
  };
  return largest_double_where(at_most, sign * root - to_double(reach));
}

/// The largest double whose square is at most `squared` (>= 0): the distance rounded down,
/// exactly, as signed_distance_down with a reach of 0.
template <class Number, class ToDouble>
double root_down(const Number& squared, ToDouble to_double) {
  return signed_distance_down(1, squared, Number(0), to_double);
}
inline double root_down(const Rational& squared) {
  return root_down(squared, [](const Rational& q) { return to_double(q); });
}

}  // namespace cc::exact
