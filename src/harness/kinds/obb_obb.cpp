// The obb_obb kind: boxes against a face of each other (exactly for exactly orthonormal axes and
// simple values), nearly parallel edges, common centres, and pairs in the regimes of
// test_obb_obb's bound slid to an exact margin. The library's call, and what its cases are.
#include "harness/kinds/obb_obb.h"

#include <cmath>

#include "collide/obb_bound.h"
#include "collide/record_sink.h"
#include "harness/generation/regimes.h"
#include "harness/generation/rotation.h"
#include "harness/generation/shapes.h"
#include "harness/generation/touch.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"

namespace cc::harness {
namespace {

// Two boxes at an exact margin of the decision, in the regimes of test_obb_obb's bound: b slid
// from a's centre along a face normal, an edge-edge axis or any direction.
ObbObbInput obb_pair_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  const ObbPair in = obb_pair_in_regime(v);
  const Vec3 w = slide_direction(v, in.a, in.b);
  const Obb &a = in.a, &b = in.b;
  const auto placed = [&a, &b, &w](double s) -> ObbObbInput {
    Obb moved = b;
    moved.center = a.center + s * w;
    return {a, moved};
  };
  const double contact = (reach_along(a, w) + reach_along(b, w)) / dot(w, w);  // along a separating w
  const double apart = 2 * contact + std::sqrt(max_abs(a.half) + max_abs(b.half)) + 1 / std::sqrt(dot(w, w));
  const double s = place_at([&placed](double t) -> Input { return placed(t); }, 0, apart,
                            draw_margin_target(v.choices()), options, contact);
  return placed(s);
}

constexpr std::string_view kConfigurations[] = {
    "touching",  "just apart", "just overlapping", "parallel axes", "nearly parallel axes", "frame at the tolerance",
    "flat box", "segment box", "point box",        "long box",      "sizes far apart",      "far from the origin"};

constexpr BoundTerm kBoundTerms[] = {
    {"test_obb_obb", "axis", "rounding"}, {"test_obb_obb", "axis", "frame"}, {"test_obb_obb", "axis", "total"}};

}  // namespace

Answer Query<ObbObbInput>::ask(const ObbObbInput& in) { return Answer::of(test_obb_obb(in.a, in.b)); }

ObbObbInput Query<ObbObbInput>::generate(ValueSource& v, const GenerateOptions& options) {
  if (v.choices().chance(35)) return obb_pair_at_the_bound(v, options);
  ObbObbInput in;
  in.a = draw_obb(v, options);
  in.b = draw_obb(v, options);
  const auto mode = v.choices().draw(5);
  if (mode == 1 || mode == 3) in.b.axes = draw_rotation_near(v, in.a.axes);  // nearly parallel edges
  if (mode >= 1 && mode <= 3) {
    // B against a face of A: exact for exactly orthonormal axes and simple values, else within ULPs.
    place_against_face(in.a, in.b, v, mode == 2);
  } else if (mode == 4) {
    in.b.center = in.a.center;
  }
  return in;
}

void Query<ObbObbInput>::touch(ObbObbInput& in, ValueSource& v) { place_against_face(in.a, in.b, v, false); }

Features Query<ObbObbInput>::features(const ObbObbInput& in) { return obb_pair_features(in.a, in.b); }

std::span<const std::string_view> Query<ObbObbInput>::configurations() { return kConfigurations; }

void Query<ObbObbInput>::recognise(const ObbObbInput& in, Configurations& found) {
  found.margins();
  found.axes_pair(in.a.axes, in.b.axes);
  found.boxes(in.a.half), found.boxes(in.b.half);
  const double sa = max_abs(in.a.half), sb = max_abs(in.b.half);
  found.add("sizes far apart", std::min(sa, sb) > 0 && std::max(sa, sb) >= kFar * std::min(sa, sb));
  found.far(std::max(max_abs(in.a.center), max_abs(in.b.center)), std::max(sa, sb));
}

std::span<const BoundTerm> Query<ObbObbInput>::bound_terms() { return kBoundTerms; }

void Query<ObbObbInput>::probe(const ObbObbInput& in, std::vector<bounds::Records>& records) {
  test_obb_obb(in.a, in.b, bounds::next_call(records));
}

}  // namespace cc::harness
