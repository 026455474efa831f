// The exact reference's pieces of a query kind: its verdict and the reasoning behind it, defined
// in the kind's unit, oracle/exact/kinds/<kind>.cpp, as judge<its input> and explain<its input>.
// A kind whose unit lacks one fails to link (exact_reference.cpp asks every kind's).
#pragma once

#include "harness/model/explanation.h"
#include "harness/model/input.h"
#include "harness/model/oracle.h"

namespace cc::exact {

using harness::ExactVerdict;

/// The exact verdict on `in`: in or out of the library's contract, the answer and its margin.
template <class In>
ExactVerdict judge(const In& in);

/// The reasoning behind judge(in), for triage, for inputs in the library's contract.
template <class In>
harness::Explanation explain(const In& in);

}  // namespace cc::exact
