// aabb_aabb in exact arithmetic: the boxes meet iff on every axis the intervals overlap.
// Margin: the smallest per-axis overlap min(hi_a, hi_b) - max(lo_a, lo_b): the depth when >= 0,
// minus the largest gap when < 0.
#include <algorithm>
#include <cmath>

#include "oracle/exact/domain.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

template <>
ExactVerdict judge(const harness::AabbAabbInput& in) {
  const Aabb &a = in.a, &b = in.b;
  const std::initializer_list<double> all = {a.lo.x, a.lo.y, a.lo.z, a.hi.x, a.hi.y, a.hi.z,
                                             b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z};
  // The documented answer out of the domain is the same per-axis comparison; comparisons of
  // doubles are exact, also with infinities, and false with NaN.
  const auto formula = [&] {
    bool hit = true;
    for (int k = 0; k < 3; ++k) hit = hit && a.lo[k] <= b.hi[k] && b.lo[k] <= a.hi[k];
    return hit;
  };
  if (has_nan(all)) return documented(false, "NaN input");
  if (!all_finite(all)) return documented(formula(), "infinite bound: compared as extended reals");
  for (int k = 0; k < 3; ++k) {
    if (a.lo[k] > a.hi[k] || b.lo[k] > b.hi[k]) return documented(formula(), "inverted box");
  }

  std::optional<Rational> overlap;
  for (int k = 0; k < 3; ++k) {
    const Rational high = std::min(rational(a.hi[k]), rational(b.hi[k]));
    const Rational low = std::max(rational(a.lo[k]), rational(b.lo[k]));
    const Rational o = high - low;
    if (!overlap || o < *overlap) overlap = o;
  }
  ExactVerdict v;
  v.answer.hit = sgn(*overlap) >= 0;
  v.margin = signed_margin(to_double(*overlap) / scale_of(max_magnitude(all)), sgn(*overlap));
  return v;
}

template <>
harness::Explanation explain(const harness::AabbAabbInput& in) {
  using harness::Explanation;
  Explanation e;
  e.title = "axes";
  e.columns = {"axis", "A", "B", "overlap"};
  const char* const names[] = {"x", "y", "z"};
  double worst = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const double overlap = std::min(in.a.hi[k], in.b.hi[k]) - std::max(in.a.lo[k], in.b.lo[k]);
    e.rows.push_back({names[k], interval(in.a.lo[k], in.a.hi[k]), interval(in.b.lo[k], in.b.hi[k]), num(overlap)});
    if (overlap < worst) {
      worst = overlap, e.deciding_row = k;
      e.a_lo = in.a.lo[k], e.a_hi = in.a.hi[k], e.b_lo = in.b.lo[k], e.b_hi = in.b.hi[k];
      Vec3 axis;
      axis[k] = 1;
      e.axis = axis;
    }
  }
  e.deciding = "the smallest overlap (a comparison of inputs: exact)";
  e.deciding_value = worst;
  return e;
}

}  // namespace cc::exact
