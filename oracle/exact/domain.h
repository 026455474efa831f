// The library's documented domains, as the exact reference checks them.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>

#include "collide/obb.h"
#include "collide/triangle.h"
#include "harness/model/oracle.h"

namespace cc::exact {

/// A verdict for inputs the library documents an answer for out of its domain.
harness::ExactVerdict documented(bool answer, std::string why);
/// A verdict for inputs outside the domain with no documented answer: no verdict (not decided).
harness::ExactVerdict unspecified(std::string why);

/// A verdict the reference decided (rationals have no range limit) for finite inputs outside the
/// library's range: the same answer and margin, marked out of contract (unspecified) and why.
harness::ExactVerdict beyond_range(harness::ExactVerdict decided, std::string why);

bool has_nan(std::initializer_list<double> values);
bool all_finite(std::initializer_list<double> values);
bool all_finite(const Triangle& t);
bool all_finite(const Obb& b);

/// The inputs' scale: the largest magnitude of their coordinates, or 1 when all are 0.
double scale_of(double largest_magnitude);

/// A margin computed in doubles (`rounded`, a length over the scale) with the sign of the exact
/// quantity that decides the case (exact_sign: > 0 overlapping, 0 touching, < 0 apart): a margin
/// that underflows to 0 while the shapes do not touch becomes the smallest subnormal of its sign,
/// so that a margin is 0 only for touching shapes.
double signed_margin(double rounded, int exact_sign);

/// Why a scale lies outside [2^min_exponent, 2^max_exponent], or nothing when it does not.
std::optional<std::string> scale_outside(double largest_magnitude, int min_exponent, int max_exponent);

/// Why a box's axes are further than kObbOrthonormalTolerance from orthonormal, if they are.
std::optional<std::string> not_orthonormal(const Mat3& axes);

}  // namespace cc::exact
