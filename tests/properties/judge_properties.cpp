// The judge is tight: a right answer moved to each bound the exact reference allows is judged
// right (or within the band), and moved one ulp past it, wrong.
//  - ray_aabb's t_enter and t_exit: the band's relative width around the exact parameter, the
//    bounds found here by exact comparisons of neighbouring doubles;
//  - moving_obb's t_first and t_last: the ranges of the exact verdict, each end checked against
//    the exact windows computed here (of the boxes, and of the boxes grown by the band): the
//    nearest doubles on the allowed side, not one ulp further;
//  - ray_mesh's t: the range of the exact verdict, whose upper end is the exact first point
//    rounded up.
// (The margins' bands are checked the same way in tests/harness/judging/classify_test.cpp.)
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>

#include "harness/judging/bands.h"
#include "harness/judging/classify.h"
#include "harness/formats/input_json.h"
#include "harness/formats/number_text.h"
#include "oracle/exact/exact_reference.h"
#include "oracle/exact/exact_sweep.h"
#include "oracle/exact/rational.h"
#include "case_budget.h"
#include "properties/property.h"

namespace cc::test {
namespace {

using namespace harness;
using exact::Rational;
using exact::rational;

// The largest double <= q and the smallest double >= q, found by exact comparisons of
// neighbours (independently of the reference's own rounding helpers); q must lie in the range
// of doubles.
double largest_at_most(const Rational& q) {
  double x = q.get_d();
  while (rational(x) > q) x = std::nextafter(x, -INFINITY);
  while (std::isfinite(std::nextafter(x, INFINITY)) && rational(std::nextafter(x, INFINITY)) <= q) x = std::nextafter(x, INFINITY);
  return x;
}
double smallest_at_least(const Rational& q) { return -largest_at_most(-q); }

Standing standing_of(QueryKind kind, const Answer& said, const ExactVerdict& exact) {
  return classify(kind, said, exact, {}).parties[0].standing;
}

// The answer `right` with parameter i moved to `t`, as the library would give it.
Answer with_param(Answer right, std::size_t i, double t) {
  right.params[i] = t;
  return right;
}

// Parameter i at `at` is not wrong, and one ulp past it (toward `past`) is.
void expect_tight(QueryKind kind, const ExactVerdict& exact, std::size_t i, double at, double past, int& checked,
                  const std::string& what) {
  if (!std::isfinite(at)) return;
  const double beyond = std::nextafter(at, past);
  if (!std::isfinite(beyond)) return;
  ++checked;
  if (standing_of(kind, with_param(exact.answer, i, at), exact) == Standing::wrong) {
    RC_FAIL(what + ": " + format_double(at) + " is allowed, but judged wrong");
  }
  if (standing_of(kind, with_param(exact.answer, i, beyond), exact) != Standing::wrong) {
    RC_FAIL(what + ": " + format_double(beyond) + ", one ulp past the bound " + format_double(at) + ", is not judged wrong");
  }
}

TEST(Judge, RayParametersOneUlpPastTheBandAreWrong) {
  const exact::ExactRationalReference reference;
  const Band band = library_band(QueryKind::ray_aabb);
  Met met;
  int checked = 0;
  const bool passed = check_property("ray_aabb: t one ulp past the band", QueryKind::ray_aabb, 0, 2000, met, [&](const Input& in) {
    const ExactVerdict v = reference.judge(in);
    met.count(features_of(in, v));
    if (v.contract != Contract::in || !v.answer.hit) return;
    for (std::size_t i = 0; i < v.answer.params.size(); ++i) {
      const double e = v.answer.params[i];
      // Below 2^-950 (0 aside) the relative term 2^-50 |e| is near or below the subnormal grid
      // and classify's floating-point bound rounds it: it may allow one subnormal ulp (2^-1074)
      // more than the exact bound. Elsewhere its bound is the exact one (the sum drops 2^-1060
      // only where no double lies within it).
      if (!std::isfinite(e) || (e != 0 && std::fabs(e) < 0x1p-950)) continue;
      // |t - e| <= width |e| + 2^-1060, the band's definition, in exact arithmetic.
      const Rational reach = rational(band.param_width) * abs(rational(e)) + rational(0x1p-1060);
      const std::string what = "ray_aabb parameter " + std::to_string(i) + " " + input_to_json(in).dump();
      expect_tight(QueryKind::ray_aabb, v, i, largest_at_most(rational(e) + reach), INFINITY, checked, what);
      expect_tight(QueryKind::ray_aabb, v, i, smallest_at_least(rational(e) - reach), -INFINITY, checked, what);
    }
  });
  EXPECT_TRUE(passed);
  EXPECT_GT(checked, 1000);
  expect_met_the_boundary("ray_aabb: t one ulp past the band", QueryKind::ray_aabb, met);
}

TEST(Judge, MovingBoxTimesOneUlpPastTheirRangesAreWrong) {
  const exact::ExactRationalReference reference;
  Met met;
  int checked = 0;
  const bool passed = check_property("moving_obb: times one ulp past their ranges", QueryKind::moving_obb, 0, 600, met,
                                     [&](const Input& in) {
    const ExactVerdict v = reference.judge(in);
    met.count(features_of(in, v));
    if (v.contract != Contract::in || !v.answer.hit) return;
    RC_ASSERT(v.param_ranges.size() == 2u);
    // The windows, computed here: the exact one and the one of the boxes grown by the band.
    const auto& m = std::get<MovingObbInput>(in);
    const std::vector<exact::MovingAxis> axes = exact::moving_axes(m.a, m.b);
    double magnitude = 0;
    for (const MovingObb* b : {&m.a, &m.b}) magnitude = std::max({magnitude, max_abs(b->box.center), max_abs(b->box.half), max_abs(b->velocity)});
    const exact::ExactWindow window = exact::exact_sweep(axes);
    const exact::ExactWindow grown =
        exact::exact_sweep(axes, rational(library_band(QueryKind::moving_obb).width * (magnitude > 0 ? magnitude : 1.0)));
    const std::string what = "moving_obb " + input_to_json(in).dump();
    // t_first in [grown.first, window.first], t_last in [window.last, grown.last], to the nearest
    // doubles on the allowed side.
    const double bounds[2][2] = {{largest_at_most(grown.first) , smallest_at_least(window.first)},
                                 {largest_at_most(window.last), smallest_at_least(grown.last)}};
    for (std::size_t i = 0; i < 2; ++i) {
      if (v.param_ranges[i].first != bounds[i][0] || v.param_ranges[i].second != bounds[i][1]) {
        RC_FAIL(what + ": the range of parameter " + std::to_string(i) + " is [" + format_double(v.param_ranges[i].first) +
                ", " + format_double(v.param_ranges[i].second) + "], the nearest doubles are [" + format_double(bounds[i][0]) +
                ", " + format_double(bounds[i][1]) + "]");
      }
      expect_tight(QueryKind::moving_obb, v, i, bounds[i][0], -INFINITY, checked, what);
      expect_tight(QueryKind::moving_obb, v, i, bounds[i][1], INFINITY, checked, what);
    }
  });
  EXPECT_TRUE(passed);
  EXPECT_GT(checked, 400);
  expect_met_the_boundary("moving_obb: times one ulp past their ranges", QueryKind::moving_obb, met);
}

TEST(Judge, ARayMeshTOneUlpPastItsRangeIsWrong) {
  const exact::ExactRationalReference reference;
  Met met;
  int checked = 0;
  const bool passed = check_property("ray_mesh: t one ulp past its range", QueryKind::ray_mesh, 0, case_budget(QueryKind::ray_mesh, 0, 60),
                                     met, [&](const Input& in) {
    const ExactVerdict v = reference.judge(in);
    met.count(features_of(in, v));
    if (v.contract != Contract::in || !v.answer.hit) return;
    RC_ASSERT(v.param_ranges.size() == 1u && v.answer.params.size() == 1u);
    const auto [lo, hi] = v.param_ranges[0];
    // The upper end is the exact first point rounded up: the double nearest to it, or the next.
    const double nearest = v.answer.params[0];
    if (!(hi == nearest || hi == std::nextafter(nearest, INFINITY))) RC_FAIL("the range's upper end is not the first point rounded up");
    const std::string what = "ray_mesh " + input_to_json(in).dump();
    expect_tight(QueryKind::ray_mesh, v, 0, lo, -INFINITY, checked, what);
    expect_tight(QueryKind::ray_mesh, v, 0, hi, INFINITY, checked, what);
  });
  EXPECT_TRUE(passed);
  EXPECT_GT(checked, 30);
}

}  // namespace
}  // namespace cc::test
