// tri_obb_distance in exact arithmetic: a triangle and a parallelepiped (the box's axes as given)
// and the signed distance from the origin to the boundary of the exact hull of their Minkowski
// difference (exact_polytope_distance.h): apart, their distance; overlapping, minus the
// penetration depth. Held as a square, so no root is rounded; an answer's points are checked on
// the triangle and on the box's faces.
#include <algorithm>

#include "oracle/exact/distance_check.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/exact_polytope_distance.h"
#include "oracle/exact/exact_polytopes.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {
namespace {

// The library's domain for distances: finite, of magnitude at most 2^500.
constexpr int kDistanceMaxExponent = 500;

ExactSignedDistance signed_distance(const harness::TriObbDistanceInput& in) {
  const auto t = triangle_corners(in.tri);
  const auto b = box_corners(in.box);
  return exact_polytope_distance(t, b);
}

}  // namespace

template <>
ExactVerdict judge(const harness::TriObbDistanceInput& in) {
  if (!all_finite(in.tri)) return documented(false, "NaN or infinite input");
  if (auto out = obb_outside_domain(in.box)) return *out;
  if (auto why = not_orthonormal(in.box.axes)) return unspecified(*why);
  const double magnitude = std::max(magnitude_of(in.tri), magnitude_of(in.box));
  ExactVerdict v = distance_verdict(signed_distance(in), magnitude, boundary_of(in.tri), boundary_of(in.box));
  if (auto why = scale_outside(magnitude, -1074, kDistanceMaxExponent)) return beyond_range(std::move(v), *why);
  return v;
}

template <>
harness::Explanation explain(const harness::TriObbDistanceInput& in) {
  harness::Explanation e = explain_polytopes(shape_of(in.tri, "T"), shape_of(in.box, "B"));
  if (!all_finite(in.tri) || obb_outside_domain(in.box)) return e;
  const ExactSignedDistance d = signed_distance(in);
  e.facts.emplace_back(d.sign < 0 ? "exact penetration depth (rounded)" : "exact distance (rounded)", num(root_of(d.squared)));
  e.facts.emplace_back("exact signed distance (rounded down)", num(rounded_down(d)));
  return e;
}

}  // namespace cc::exact
