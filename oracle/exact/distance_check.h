// The exact check of a distance query's answer (ExactVerdict::check_distance), for any two shapes
// given by their exact squared distance and the exact squared distance from a point to each.
#pragma once

#include <functional>

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
/// exactly (the largest finite double beyond them).
double root_down(const Rational& squared);

}  // namespace cc::exact
