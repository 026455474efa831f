// obb_obb in exact arithmetic: two parallelepipeds through the exact separating-axis test,
// filtered (filtered_sat.h).
#include <algorithm>

#include "oracle/exact/domain.h"
#include "oracle/exact/exact_polytopes.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/filtered_sat.h"
#include "oracle/exact/judges.h"

namespace cc::exact {

template <>
ExactVerdict judge(const harness::ObbObbInput& in) {
  for (const Obb* b : {&in.a, &in.b}) {
    if (auto out = obb_outside_domain(*b)) return *out;
  }
  const double magnitude = std::max(magnitude_of(in.a), magnitude_of(in.b));
  for (const Obb* b : {&in.a, &in.b}) {
    if (auto why = not_orthonormal(b->axes)) return unspecified(*why);
  }
  const ExactVerdict v = verdict_of(sat_verdict(in.a, in.b), magnitude);
  // Decided all the same beyond the library's range: rationals have none.
  if (auto why = scale_outside(magnitude, kObbMinExponent, kObbMaxExponent)) return beyond_range(v, *why);
  return v;
}

template <>
harness::Explanation explain(const harness::ObbObbInput& in) {
  return explain_polytopes(shape_of(in.a, "A"), shape_of(in.b, "B"));
}

}  // namespace cc::exact
