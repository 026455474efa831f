// tri_tri_distance in exact arithmetic: whether the triangles meet and how far from touching, as
// the two-triangle test's judge decides it (the exact separating-axis test); their squared
// distance, the least over each vertex against the other triangle and each pair of edges
// (exact_distance.h), against which an answer's distance and points are checked.
#include <algorithm>
#include <cstdio>
#include <string>

#include "harness/kinds/tri_tri.h"
#include "oracle/exact/distance_check.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/exact_distance.h"
#include "oracle/exact/exact_polytopes.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {

template <>
ExactVerdict judge(const harness::TriTriInput& in);
template <>
harness::Explanation explain(const harness::TriTriInput& in);

namespace {

// The library's domain for distances: finite coordinates of magnitude at most 2^500.
constexpr int kDistanceMaxExponent = 500;

}  // namespace

template <>
ExactVerdict judge(const harness::TriTriDistanceInput& in) {
  ExactVerdict v = judge(harness::TriTriInput{in.a, in.b});
  if (!all_finite(in.a) || !all_finite(in.b)) return v;  // documented: NaN, a miss
  const double magnitude = std::max(magnitude_of(in.a), magnitude_of(in.b));
  if (v.contract != harness::Contract::in) {
    // The two-triangle test's range is narrower ([2^-300, 2^300]): distances are in the domain
    // up to 2^500 and down to 0.
    if (scale_outside(magnitude, -1074, kDistanceMaxExponent)) return v;
    v.contract = harness::Contract::in;
    v.note.clear();
  }
  const ExactSignedDistance exact{squared_distance_between_triangles(in.a, in.b)};
  v.answer.params = {rounded_down(exact)};
  v.scale = scale_of(magnitude);
  v.check_distance = distance_check(exact, boundary_of(in.a), boundary_of(in.b));
  return v;
}

template <>
harness::Explanation explain(const harness::TriTriDistanceInput& in) {
  harness::Explanation e = explain(harness::TriTriInput{in.a, in.b});
  if (!all_finite(in.a) || !all_finite(in.b)) return e;
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", root_down(squared_distance_between_triangles(in.a, in.b)));
  e.facts.emplace_back("exact distance (rounded down)", text);
  return e;
}

}  // namespace cc::exact
