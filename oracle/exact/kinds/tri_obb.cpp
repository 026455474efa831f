// tri_obb in exact arithmetic: a parallelepiped and a triangle through the exact
// separating-axis test, filtered (filtered_sat.h).
#include <algorithm>

#include "oracle/exact/domain.h"
#include "oracle/exact/exact_polytopes.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/filtered_sat.h"
#include "oracle/exact/judges.h"

namespace cc::exact {

template <>
ExactVerdict judge(const harness::TriObbInput& in) {
  if (!all_finite(in.tri)) return documented(false, "NaN or infinite input");
  if (auto out = obb_outside_domain(in.box)) return *out;
  const double magnitude = std::max(magnitude_of(in.tri), magnitude_of(in.box));
  if (auto why = not_orthonormal(in.box.axes)) return unspecified(*why);
  const ExactVerdict v = verdict_of(sat_verdict(in.box, in.tri), magnitude);
  // Decided all the same beyond the library's range: rationals have none.
  if (auto why = scale_outside(magnitude, kTriangleMinExponent, kTriangleMaxExponent)) return beyond_range(v, *why);
  return v;
}

template <>
harness::Explanation explain(const harness::TriObbInput& in) {
  return explain_polytopes(shape_of(in.box, "B"), shape_of(in.tri, "T"));
}

}  // namespace cc::exact
