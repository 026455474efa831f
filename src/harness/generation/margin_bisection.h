// Placing a case at an exact margin: a one-parameter family of cases (a shape slid along a
// direction, a ray moved sideways) is searched for the parameter at which the exact reference's
// margin crosses a target, by secant steps and then bisection down to adjacent doubles. The
// generators reach the exact reference only through ExactReference (oracle.h).
#pragma once

#include <functional>
#include <optional>

#include "harness/model/input.h"
#include "harness/model/oracle.h"

namespace cc::harness {

/// The cases family(s) for a parameter s.
using Family = std::function<Input(double s)>;

/// Which side of the target margin to return.
enum class Side {
  inside,   // the last parameter whose exact margin is at least the target (for 0: a hit)
  outside,  // the first parameter beyond it
};

/// A parameter s at which the exact margin of family(s) crosses `target` (ExactVerdict::margin
/// units: relative to the inputs' scale): of two adjacent doubles, one on each side, the one on
/// `side`. The search starts from s0 and s1 (a first step; the crossing may lie anywhere) and
/// asks the reference at most `max_judgements` times; out of judgements with the crossing
/// bracketed, it returns the end of the bracket on `side`. Nothing when no crossing is found, or
/// a case leaves the domain or cannot be decided.
std::optional<double> bisect_to_margin(const Family& family, double s0, double s1, double target, Side side,
                                       const ExactReference& exact, int max_judgements = 64);

}  // namespace cc::harness
