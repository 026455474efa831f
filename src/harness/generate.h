// Case generators, one per kind of query, biased toward the decision boundary: shapes made to
// touch by construction, coordinates equal or a few ULPs apart, parallel and degenerate
// configurations, and the extreme values of ValueSource.
#pragma once

#include "harness/choices.h"
#include "harness/input.h"

namespace cc::harness {

struct GenerateOptions {
  /// Also NaN, infinities and shapes outside the library's domains (negative radii, inverted
  /// boxes, non-orthonormal axes).
  bool out_of_contract = false;
};

Input generate(QueryKind kind, Choices& choices, const GenerateOptions& options = {});

}  // namespace cc::harness
