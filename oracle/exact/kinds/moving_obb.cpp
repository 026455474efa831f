// moving_obb in exact arithmetic: the window of times at which the boxes (parallelepipeds, axes
// as given) meet, the margin of the closest approach, and the ranges the library's first and last
// times must fall in: between the exact window and the window of the boxes grown by its band.
#include <algorithm>
#include <cmath>
#include <limits>

#include "harness/judging/bands.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/exact_sweep.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {
namespace {

constexpr int kMinExponent = -500, kMaxExponent = 500;

double magnitude_of(const MovingObb& m) {
  return std::max({max_abs(m.box.center), max_abs(m.box.half), max_abs(m.velocity)});
}

// q / unit as a double (neither overflowing nor underflowing on the way).
double ratio(const Rational& q, Magnitude unit) { return (Magnitude::of(q) / unit).to_double(); }


// Minus the least, over t in [0, 1], of the largest gap (|p + t s| - r) / conditioning over the
// axes, in units of the scale: the margin of the closest approach (< 0 apart). The gaps are
// lines in t, so the least of their maximum lies at 0, at 1 or where two lines cross.
double closest_approach_margin(const std::vector<MovingAxis>& axes, double scale) {
  struct Line {
    double a, b;  // a + b t
  };
  std::vector<Line> lines;
  const Magnitude unit_scale = Magnitude::of(rational(scale));
  for (const MovingAxis& m : axes) {
    const Magnitude unit = m.axis.conditioning * unit_scale;
    const double p = ratio(m.p, unit), s = ratio(m.s, unit), r = ratio(m.r, unit);
    lines.push_back({p - r, s});
    lines.push_back({-p - r, -s});
  }
  const auto worst_gap = [&](double t) {
    double g = -std::numeric_limits<double>::infinity();
    for (const Line& l : lines) g = std::max(g, l.a + l.b * t);
    return g;
  };
  double least = std::min(worst_gap(0), worst_gap(1));
  for (std::size_t i = 0; i < lines.size(); ++i) {
    for (std::size_t j = i + 1; j < lines.size(); ++j) {
      if (lines[i].b == lines[j].b) continue;
      const double t = (lines[j].a - lines[i].a) / (lines[i].b - lines[j].b);
      if (t > 0 && t < 1) least = std::min(least, worst_gap(t));
    }
  }
  return -least;
}

}  // namespace

template <>
ExactVerdict judge(const harness::MovingObbInput& in) {
  for (const MovingObb* m : {&in.a, &in.b}) {
    if (!all_finite(m->box) || !all_finite({m->velocity.x, m->velocity.y, m->velocity.z})) {
      return documented(false, "NaN or infinite input");
    }
    if (m->box.half.x < 0 || m->box.half.y < 0 || m->box.half.z < 0) return documented(false, "negative half extent");
  }
  const double magnitude = std::max(magnitude_of(in.a), magnitude_of(in.b));
  if (auto why = scale_outside(magnitude, kMinExponent, kMaxExponent)) return unspecified(*why);
  for (const MovingObb* m : {&in.a, &in.b}) {
    if (auto why = not_orthonormal(m->box.axes)) return unspecified(*why);
  }
  const double scale = scale_of(magnitude);
  const std::vector<MovingAxis> axes = moving_axes(in.a, in.b);
  const ExactWindow window = exact_sweep(axes);
  ExactVerdict v;
  v.answer.hit = window.hit();
  if (!v.answer.hit) {  // apart at every time: the closest approach, below 0
    v.margin = std::min(closest_approach_margin(axes, scale), -std::numeric_limits<double>::denorm_min());
    return v;
  }
  v.answer.params = {to_double(window.first), to_double(window.last)};
  // A hit's margin: how deep the boxes overlap halfway through the window (0 if they only touch).
  const Rational middle = (window.first + window.last) / 2;
  double depth = std::numeric_limits<double>::infinity();
  for (const MovingAxis& m : axes) {
    const Rational overlap = m.r - abs(m.p + middle * m.s);
    depth = std::min(depth, ratio(overlap, length(m.axis.axis) * Magnitude::of(rational(scale))));
  }
  v.margin = std::max(depth, 0.0);
  const ExactWindow grown = exact_sweep(axes, rational(harness::library_band(harness::QueryKind::moving_obb).width * scale));
  v.param_ranges = {{round_down(grown.first), round_up(window.first)}, {round_down(window.last), round_up(grown.last)}};
  return v;
}

// Per candidate axis: the projected centres' offset p + t s against the radii r, and the
// times at which the projections overlap.
template <>
harness::Explanation explain(const harness::MovingObbInput& in) {
  using harness::Explanation;
  const harness::ExactVerdict v = judge(in);
  Explanation e;
  e.title = "moving separating axes: |p + t s| <= r";
  if (v.contract != harness::Contract::in) {
    e.deciding = v.note;
    return e;
  }
  e.columns = {"axis", "p", "s", "r", "times"};
  const std::vector<MovingAxis> axes = moving_axes(in.a, in.b);
  for (const MovingAxis& m : axes) {
    ExactWindow w;
    w.restrict(m.p, m.s, m.r);
    e.rows.push_back({m.axis.name, num(m.p), num(m.s), num(m.r), w.hit() ? interval(to_double(w.first), to_double(w.last)) : "never"});
  }
  const ExactWindow window = exact_sweep(axes);
  e.facts.push_back({"window", window.hit() ? interval(to_double(window.first), to_double(window.last)) : "empty"});
  if (v.answer.hit) {
    e.facts.push_back({"t_first allowed", interval(v.param_ranges[0].first, v.param_ranges[0].second)});
    e.facts.push_back({"t_last allowed", interval(v.param_ranges[1].first, v.param_ranges[1].second)});
  }
  e.deciding = v.answer.hit ? "overlap halfway through the window, relative to the scale"
                            : "the closest approach: minus the largest gap over the axes, relative to the scale";
  e.deciding_value = v.margin;
  return e;
}

}  // namespace cc::exact
