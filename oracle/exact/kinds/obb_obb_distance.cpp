// obb_obb_distance in exact arithmetic: two parallelepipeds (their axes as given) and the signed
// distance from the origin to the boundary of the exact hull of their Minkowski difference
// (exact_polytope_distance.h): apart, their distance; overlapping, minus the penetration depth.
// Held as a square, so no root is rounded; an answer's points are checked on the boxes' faces.
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

ExactSignedDistance signed_distance(const harness::ObbObbDistanceInput& in) {
  const auto a = box_corners(in.a), b = box_corners(in.b);
  return exact_polytope_distance(a, b);
}

}  // namespace

template <>
ExactVerdict judge(const harness::ObbObbDistanceInput& in) {
  for (const Obb* b : {&in.a, &in.b}) {
    if (auto out = obb_outside_domain(*b)) return *out;
  }
  for (const Obb* b : {&in.a, &in.b}) {
    if (auto why = not_orthonormal(b->axes)) return unspecified(*why);
  }
  const double magnitude = std::max(magnitude_of(in.a), magnitude_of(in.b));
  ExactVerdict v = distance_verdict(signed_distance(in), magnitude, boundary_of(in.a), boundary_of(in.b));
  if (auto why = scale_outside(magnitude, -1074, kDistanceMaxExponent)) return beyond_range(std::move(v), *why);
  return v;
}

template <>
harness::Explanation explain(const harness::ObbObbDistanceInput& in) {
  harness::Explanation e = explain_polytopes(shape_of(in.a, "A"), shape_of(in.b, "B"));
  if (obb_outside_domain(in.a) || obb_outside_domain(in.b)) return e;
  const ExactSignedDistance d = signed_distance(in);
  e.facts.emplace_back(d.sign < 0 ? "exact penetration depth (rounded)" : "exact distance (rounded)", num(root_of(d.squared)));
  e.facts.emplace_back("exact signed distance (rounded down)", num(rounded_down(d)));
  return e;
}

}  // namespace cc::exact
