// tri_tri in exact arithmetic: two triangles through the exact separating-axis test, in integer
// arithmetic where it takes them (triangle_sat.h), its reasoning through exact_polytopes.h.
#include <algorithm>

#include "oracle/exact/domain.h"
#include "oracle/exact/exact_polytopes.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {

template <>
ExactVerdict judge(const harness::TriTriInput& in) {
  if (!all_finite(in.a) || !all_finite(in.b)) return documented(false, "NaN or infinite input");
  const double magnitude = std::max(magnitude_of(in.a), magnitude_of(in.b));
  const ExactVerdict v = verdict_of(triangle_pair_sat(in.a, in.b), magnitude);
  // Decided all the same beyond the library's range: rationals have none.
  if (auto why = scale_outside(magnitude, kTriangleMinExponent, kTriangleMaxExponent)) return beyond_range(v, *why);
  return v;
}

template <>
harness::Explanation explain(const harness::TriTriInput& in) {
  return explain_polytopes(shape_of(in.a, "A"), shape_of(in.b, "B"));
}

}  // namespace cc::exact
