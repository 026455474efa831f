// bisect_to_margin (harness/generation/margin_bisection.h) against margins it is told: a reference
// whose margin is a drawn function of the family's parameter, crossing its target anywhere (at 0,
// among the subnormals, at a generic point), steep or nearly flat, with a step instead of a
// slope, infinite on one side, or leaving the domain (NaN, undecided, out of contract) over a
// band of parameters; searched from ends either side of the crossing, on one side, equal or
// reversed, with budgets down to a few judgements, and through a family that gives one case for
// many parameters. Whatever it returns lies on the side it was asked for: its margin at least the
// target (inside) or below it (outside), as the reference judges it, and in the domain. Where the
// margin is a line through a crossing the ends bracket, and the search ends with judgements to
// spare, the parameter returned and the next double toward the other side lie on opposite sides
// (adjacent doubles).
// It must meet each of those situations.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>
#include <functional>
#include <limits>

#include "harness/generation/choices.h"
#include "harness/generation/margin_bisection.h"
#include "properties/property.h"

namespace cc::test {
namespace {

using namespace harness;

// The families: a ball slid along x, the parameter its centre's x; or the same on a grid of steps
// of 2^-20, so that many parameters give one case (as a family that rounds does).
Input slid(double s) { return SphereSphereInput{{{0, 0, 0}, 1}, {{s, 0, 0}, 0.3}}; }
Input slid_on_a_grid(double s) { return slid(std::ldexp(std::round(std::ldexp(s, 20)), -20)); }
double parameter_of(const Input& input) { return std::get<SphereSphereInput>(input).b.center.x; }

// A reference whose verdict is a function of the parameter.
class Told final : public ExactReference {
 public:
  explicit Told(std::function<ExactVerdict(double)> verdict) : verdict_(std::move(verdict)) {}
  ExactVerdict judge(const Input& input) const override {
    ++judgements;
    return verdict_(parameter_of(input));
  }
  Explanation explain(const Input&) const override { return {}; }
  std::vector<TermError> bound_errors(const bounds::Records&) const override { return {}; }
  mutable int judgements = 0;

 private:
  std::function<ExactVerdict(double)> verdict_;
};

ExactVerdict margin(double m) {
  ExactVerdict v;
  v.margin = m;
  return v;
}

enum Shape { line, step, infinite_beyond, nan_band, undecided_band, out_of_contract_band, flat, kShapes };

TEST(MarginBisection, ReturnsAParameterOnTheSideAskedFor) {
  int met[kShapes] = {}, adjacent = 0, none = 0, found = 0, gridded = 0, overflowing = 0;
  const bool passed = check_property_with_choices("bisect_to_margin returns a parameter on the side asked for", 3000,
                                                  [&](Choices& c) {
    const auto shape = static_cast<Shape>(c.draw(kShapes));
    // Among the subnormals: crossings at even and odd multiples of the smallest, so that the
    // midpoint of the last two ends rounds onto either of them.
    const double d = std::numeric_limits<double>::denorm_min();
    const double crossings[] = {0.0, d, 3 * d, 0x1p-1060, 1.3, 0x1p-30, static_cast<double>(c.draw(1000)) / 997};
    const double crossing = crossings[c.draw(std::size(crossings))];
    const double slope = std::ldexp(1.0, static_cast<int>(c.draw(81)) - 40) * (c.chance(20) ? 0x1p900 : 1.0);
    const double target = c.chance(50) ? 0.0 : std::ldexp(c.chance(50) ? 1.0 : -1.0, -40 - static_cast<int>(c.draw(14)));
    // The band a domain-leaving shape leaves over: beyond the crossing, reached or not, to the
    // end or (a fifth of the time) over a stretch of 2^-12, with the domain beyond it again.
    const double band = crossing + std::ldexp(1.0, -static_cast<int>(c.draw(10)));
    const double band_end = c.chance(20) ? band + 0x1p-12 : INFINITY;
    const Told told([=](double s) {
      const double m = slope * (crossing - s);  // > 0 (inside) below the crossing
      const bool banded = s > band && s < band_end;
      ExactVerdict v = margin(m);
      switch (shape) {
        case line: break;
        case step: v.margin = s < crossing ? 1.0 : s > crossing ? -1.0 : 0.0; break;
        case infinite_beyond: v.margin = banded ? -INFINITY : m; break;
        case nan_band: v.margin = banded ? NAN : m; break;
        case undecided_band: v.decided = !banded; break;
        case out_of_contract_band: v.contract = banded ? Contract::unspecified : Contract::in; break;
        case flat: v.margin = 0.25; break;
        case kShapes: break;
      }
      return v;
    });
    // The ends: either side of the crossing (near it or far), both below it, equal, or reversed.
    // A tenth of the time the first is 2^60..2^70 away, so that with the steepest slopes the
    // secant's product overflows while the search looks for the crossing.
    const double near = std::ldexp(1.0, c.chance(10) ? 60 + static_cast<int>(c.draw(11)) : -static_cast<int>(c.draw(60)));
    double s0 = crossing - near, s1 = crossing + std::ldexp(1.0, -static_cast<int>(c.draw(60)));
    switch (c.draw(4)) {
      case 0: s1 = s0 - near; break;  // both below: the crossing is looked for
      case 1: s1 = s0; break;
      case 2: std::swap(s0, s1); break;
      default: break;
    }
    const Side side = c.chance(50) ? Side::inside : Side::outside;
    const int budget = c.chance(20) ? 2 + static_cast<int>(c.draw(10)) : 200;
    const bool on_a_grid = c.chance(20);
    const Family family = on_a_grid ? Family(slid_on_a_grid) : Family(slid);
    ++met[shape];
    // Ends on one side whose secant's product (margin times step) overflows.
    const double f1 = slope * (crossing - s1);
    overflowing += shape == line && s1 < s0 && std::isfinite(f1) && std::isinf(f1 * (s1 - s0));
    gridded += on_a_grid;
    const auto s = bisect_to_margin(family, s0, s1, target, side, told, budget);
    const bool budget_left = told.judgements < budget;
    if (!s) {
      ++none;
      return;
    }
    ++found;
    const ExactVerdict v = told.judge(family(*s));
    RC_ASSERT(v.contract == Contract::in);
    RC_ASSERT(v.decided);
    RC_ASSERT(!std::isnan(v.margin));
    RC_ASSERT((v.margin - target >= 0) == (side == Side::inside));
    const double lo = std::min(s0, s1), hi = std::max(s0, s1);
    if (shape == line && !on_a_grid && budget_left && slope * (crossing - lo) - target >= 0 && slope * (crossing - hi) - target < 0 &&
        std::isfinite(slope * (crossing - lo))) {
      const double next = std::nextafter(*s, side == Side::inside ? INFINITY : -INFINITY);
      RC_ASSERT((told.judge(family(next)).margin - target >= 0) != (side == Side::inside));
      ++adjacent;
    }
  });
  EXPECT_TRUE(passed);
  for (int shape = 0; shape < kShapes; ++shape) EXPECT_GT(met[shape], 0) << "shape " << shape;
  EXPECT_GT(adjacent, 50);
  EXPECT_GT(found, 300);
  EXPECT_GT(none, 100);
  EXPECT_GT(gridded, 100);
  EXPECT_GT(overflowing, 0);
}

}  // namespace
}  // namespace cc::test
