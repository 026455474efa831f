// The bound of a computed parameter (a quotient with a few roundings), shared by the ray and
// sweep tests, and the record of one such parameter.
//
// Every bound of the library (the *_bound.h headers) is a struct of named terms that its test
// decides with; the probed versions of the tests hand the same structs to the harness
// (bound_records.h), which measures how close the actual rounding of each quantity comes to each
// term (`crosscheck bounds`). Every total() also holds fp::subnormal_slack, an allowance for
// results in the subnormal range where relative bounds fail; it is not a named term (it exceeds
// one rounding there by 2^16).
#pragma once

#include <algorithm>
#include <cmath>

#include "collide/fp.h"

namespace cc::bounds {

/// A computed parameter t (a quotient with a few roundings) moved outward: lower(t) <= t* <=
/// upper(t) whenever |t - t*| <= rounding(t), t* being its exact value. Multiplicative, so that
/// a parameter that overflowed to +-inf stays infinite (an additive pad would give inf - inf).
struct Widening {
  const char* name;  // what t is, e.g. "slab parameter"
  double relative;   // of |t|
  /// The term: how far t may be from its exact value, outside the subnormal range.
  double rounding(double t) const { return relative * std::fabs(t); }
  /// t (1 - relative) for t > 0, t (1 + relative) otherwise, less the slack: rounding is monotone,
  /// so that is the smaller of the two products (both the same double for t = +-0, NaN, +-inf).
  double lower(double t) const { return std::min(t * (1 - relative), t * (1 + relative)) - fp::subnormal_slack; }
  double upper(double t) const { return std::max(t * (1 - relative), t * (1 + relative)) + fp::subnormal_slack; }
};

/// A parameter t computed from (n1 - n2) / (d1 - d2) * 2^exponent (in whatever order of
/// operations) and certified by `widening`: its exact value is that of the recorded doubles.
struct Quotient {
  double n1, n2, d1, d2;
  int exponent;
  double t;
  Widening widening;
};

}  // namespace cc::bounds
