// tri_aabb in exact arithmetic: a box and a triangle through the exact separating-axis test,
// filtered (filtered_sat.h).
#include <algorithm>

#include "oracle/exact/domain.h"
#include "oracle/exact/exact_polytopes.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/filtered_sat.h"
#include "oracle/exact/judges.h"

namespace cc::exact {

template <>
ExactVerdict judge(const harness::TriAabbInput& in) {
  if (!all_finite(in.tri) || !all_finite({in.box.lo.x, in.box.lo.y, in.box.lo.z, in.box.hi.x, in.box.hi.y, in.box.hi.z})) {
    return documented(false, "NaN or infinite input");
  }
  for (int k = 0; k < 3; ++k) {
    if (in.box.lo[k] > in.box.hi[k]) return documented(false, "inverted box");
  }
  const double magnitude = std::max(magnitude_of(in.tri), magnitude_of(in.box));
  const ExactVerdict v = verdict_of(sat_verdict(in.box, in.tri), magnitude);
  // Decided all the same beyond the library's range: rationals have none.
  if (auto why = scale_outside(magnitude, kTriangleMinExponent, kTriangleMaxExponent)) return beyond_range(v, *why);
  return v;
}

template <>
harness::Explanation explain(const harness::TriAabbInput& in) {
  return explain_polytopes(box_shape(in.box.lo, in.box.hi, "B"), shape_of(in.tri, "T"));
}

}  // namespace cc::exact
