// tri_tri_intersection in exact arithmetic: whether the triangles meet and how far from touching,
// as the two-triangle test's judge decides it (the exact separating-axis test); where, by clipping
// one triangle to the other in rationals (exact_triangle_intersection.h), each corner with its
// condition number.
#include <algorithm>
#include <cstdio>
#include <string>

#include "harness/kinds/tri_tri.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/exact_polytopes.h"
#include "oracle/exact/exact_triangle_intersection.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {

template <>
ExactVerdict judge(const harness::TriTriInput& in);
template <>
harness::Explanation explain(const harness::TriTriInput& in);

template <>
ExactVerdict judge(const harness::TriTriIntersectionInput& in) {
  ExactVerdict v = judge(harness::TriTriInput{in.a, in.b});
  if (!v.decided || !all_finite(in.a) || !all_finite(in.b)) return v;
  const std::vector<ExactCorner> corners = exact_triangle_intersection(in.a, in.b);
  if (corners.empty() == v.answer.hit) {
    v.decided = false;
    v.note = "the exact separating-axis test and the exact clipping disagree";
    return v;
  }
  double kappa = 1;
  for (const ExactCorner& c : corners) {
    const Vec3 p = to_double(c.point);
    v.answer.params.insert(v.answer.params.end(), {p.x, p.y, p.z});
    kappa = std::max(kappa, c.condition);
  }
  // The library's bound (triangle_intersection.h), and 2^-48 M for judging in doubles: the exact
  // corners rounded to nearest and the distances computed in floating point (hull_distance.h).
  const double m = std::max(magnitude_of(in.a), magnitude_of(in.b));
  v.corner_tolerance = 0x1p-44 * m * kappa + 0x1p-48 * m + 0x1p-1074;
  return v;
}

template <>
harness::Explanation explain(const harness::TriTriIntersectionInput& in) {
  harness::Explanation e = explain(harness::TriTriInput{in.a, in.b});
  if (!all_finite(in.a) || !all_finite(in.b)) return e;
  int i = 0;
  for (const ExactCorner& c : exact_triangle_intersection(in.a, in.b)) {
    const Vec3 p = to_double(c.point);
    char text[160];
    std::snprintf(text, sizeof text, "(%.17g, %.17g, %.17g), condition number %.3g", p.x, p.y, p.z, c.condition);
    e.facts.emplace_back("corner " + std::to_string(i++), text);
  }
  if (i == 0) e.facts.emplace_back("corners", "none: the triangles do not meet");
  return e;
}

}  // namespace cc::exact
