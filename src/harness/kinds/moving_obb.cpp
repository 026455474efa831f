// The moving_obb kind: two boxes from the static pair's generator (obb_obb's: touching, nudged,
// parallel, degenerate), given velocities and moved back so that they meet at a chosen time of
// the step: 0, a quarter, a half or the end, or never; with equal velocities (no relative
// motion), equal velocity components (a rate of exactly 0 on an axis), and axis-aligned boxes
// with exact bounds. The library's calls, and what its cases are.
#include "harness/kinds/moving_obb.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "collide/obb_bound.h"
#include "collide/record_sink.h"
#include "collide/sweep_bound.h"
#include "harness/generation/regimes.h"
#include "harness/generation/shapes.h"
#include "harness/generation/touch.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"
#include "harness/kinds/obb_obb.h"

namespace cc::harness {
namespace {

// Two boxes in the regimes of sweep_obb_obb's bound (those of test_obb_obb, with velocities up to
// 2^30 times the boxes' size), b slid so that the boxes meet, at an exact margin, at time tau.
MovingObbInput moving_pair_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  const ObbPair boxes = obb_pair_in_regime(v);
  const double size = std::max({max_abs(boxes.a.half), max_abs(boxes.b.half), 0x1p-20});
  MovingObbInput in{{boxes.a, {}}, {boxes.b, {}}};
  if (c.chance(70)) {
    const Vec3 direction = draw_direction(v);
    in.a.velocity = std::ldexp(size, v.small_int(30)) * direction;
  }
  in.b.velocity = in.a.velocity;
  if (!c.chance(20)) {
    const Vec3 direction = draw_direction(v);
    in.b.velocity = in.a.velocity + std::ldexp(size, v.small_int(30)) * direction;
  }
  constexpr double kTimes[] = {0, 0.25, 0.5, 1, 0.75};
  const double tau = kTimes[c.draw(std::size(kTimes))];
  const Vec3 w = slide_direction(v, boxes.a, boxes.b);
  const Vec3 back = tau * (in.b.velocity - in.a.velocity);
  const auto placed = [&in, &w, &back](double s) {
    MovingObbInput out = in;
    out.b.box.center = in.a.box.center + s * w - back;
    return out;
  };
  const double contact = (reach_along(in.a.box, w) + reach_along(in.b.box, w)) / dot(w, w);
  const double apart = 2 * contact + std::sqrt(size) + 1 / std::sqrt(dot(w, w));
  const double s = place_at([&placed](double t) -> Input { return placed(t); }, 0, apart,
                            draw_margin_target(c), options, contact);
  return placed(s);
}

// An axis-aligned moving box as the Aabb it is, if its bounds are exact.
std::optional<Aabb> exact_aabb(const MovingObb& m) {
  if (!(m.box.axes == Mat3::identity())) return std::nullopt;
  const Aabb box{m.box.center - m.box.half, m.box.center + m.box.half};
  for (int k = 0; k < 3; ++k) {
    // Both bounds exact: they give back the centre and the half extent.
    if ((box.hi[k] + box.lo[k]) * 0.5 != m.box.center[k] || (box.hi[k] - box.lo[k]) * 0.5 != m.box.half[k] ||
        box.hi[k] - m.box.center[k] != m.box.half[k] || m.box.center[k] - box.lo[k] != m.box.half[k]) {
      return std::nullopt;
    }
  }
  return box;
}

Answer sweep_answer(const SweepHit& h) {
  Answer a = Answer::of(h.hit);
  if (h.hit) a.params = {h.t_first, h.t_last};
  return a;
}

constexpr std::string_view kConfigurations[] = {
    "touching", "just apart", "parallel axes", "nearly parallel axes", "frame at the tolerance", "fast",
    "no relative motion", "point box", "far from the origin"};

constexpr BoundTerm kBoundTerms[] = {
    {"sweep_obb_obb", "axis", "rounding"},       {"sweep_obb_obb", "axis", "frame"},
    {"sweep_obb_obb", "axis", "total"},          {"sweep_obb_obb", "obb time", "rounding"},
    {"sweep_obb_obb", "obb time", "total"},      {"sweep_aabb_aabb", "aabb time", "rounding"},
    {"sweep_aabb_aabb", "aabb time", "total"}};

}  // namespace

Answer Query<MovingObbInput>::ask(const MovingObbInput& in) { return sweep_answer(sweep_obb_obb(in.a, in.b)); }

const std::vector<Party<MovingObbInput>>& Query<MovingObbInput>::library_parties() {
  static const std::vector<Party<MovingObbInput>> parties = {
      {"library.sweep_aabb_aabb", band, [](const MovingObbInput& in) {
         const auto a = exact_aabb(in.a), b = exact_aabb(in.b);
         if (!a || !b) return not_applicable("not two exact axis-aligned boxes");
         return answered(sweep_answer(sweep_aabb_aabb(*a, in.a.velocity, *b, in.b.velocity)));
       }}};
  return parties;
}

MovingObbInput Query<MovingObbInput>::generate(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  if (c.chance(35)) return moving_pair_at_the_bound(v, options);
  ObbObbInput at_contact = Query<ObbObbInput>::generate(v, options);
  if (c.chance(25)) {  // axis-aligned with simple values: sweep_aabb_aabb answers too
    for (Obb* b : {&at_contact.a, &at_contact.b}) {
      b->axes = Mat3::identity();
      for (int k = 0; k < 3; ++k) b->center[k] = 0.5 * v.small_int(8), b->half[k] = 0.5 * static_cast<double>(c.draw(5));
    }
    if (c.chance(60)) {  // faces touching on one axis
      const int k = static_cast<int>(c.draw(3));
      at_contact.b.center[k] = at_contact.a.center[k] + at_contact.a.half[k] + at_contact.b.half[k];
    }
  }
  MovingObbInput in{{at_contact.a, {}}, {at_contact.b, {}}};
  in.a.velocity = c.chance(30) ? Vec3{} : v.point();
  switch (c.draw(4)) {
    case 0: in.b.velocity = in.a.velocity; break;  // no relative motion
    case 1:                                        // a rate of exactly 0 on one axis
      in.b.velocity = v.point();
      in.b.velocity[static_cast<int>(c.draw(3))] = in.a.velocity[static_cast<int>(c.draw(3))];
      break;
    default: in.b.velocity = v.point();
  }
  // Meets (as the obb_obb case is placed) at time tau: b starts back along the relative velocity.
  constexpr double kTimes[] = {0, 0.25, 0.5, 1, 2, -1};  // 2 and -1: outside the step
  const double tau = kTimes[c.draw(std::size(kTimes))];
  in.b.box.center = in.b.box.center - tau * (in.b.velocity - in.a.velocity);
  return in;
}

void Query<MovingObbInput>::touch(MovingObbInput& in, ValueSource& v) {
  Obb b = in.b.box;
  place_against_face(in.a.box, b, v, false);
  in.b.box.center = b.center - 0.5 * (in.b.velocity - in.a.velocity);
}

Features Query<MovingObbInput>::features(const MovingObbInput& in) {
  Features f = obb_pair_features(in.a.box, in.b.box);
  const Vec3 w = in.b.velocity - in.a.velocity;
  f.parallel |= w.x == 0 || w.y == 0 || w.z == 0;
  f.degenerate |= is_zero(w);
  return f;
}

std::span<const std::string_view> Query<MovingObbInput>::configurations() { return kConfigurations; }

void Query<MovingObbInput>::recognise(const MovingObbInput& in, Configurations& found) {
  found.margins();
  found.axes_pair(in.a.box.axes, in.b.box.axes);
  const Vec3 v = in.b.velocity - in.a.velocity;
  const double size = std::max(max_abs(in.a.box.half), max_abs(in.b.box.half));
  found.add("fast", size > 0 && max_abs(v) >= kFar * size);
  found.add("no relative motion", v == Vec3{});
  found.add("point box", zero_extents(in.a.box.half) == 3 || zero_extents(in.b.box.half) == 3);
  found.far(std::max(max_abs(in.a.box.center), max_abs(in.b.box.center)), size);
}

std::span<const BoundTerm> Query<MovingObbInput>::bound_terms() { return kBoundTerms; }

void Query<MovingObbInput>::probe(const MovingObbInput& in, std::vector<bounds::Records>& records) {
  bounds::Records& r = bounds::next_call(records);
  sweep_obb_obb(in.a, in.b, r);
  if (in.a.box.axes == Mat3::identity() && in.b.box.axes == Mat3::identity()) {
    const auto box = [](const Obb& b) { return Aabb{b.center - b.half, b.center + b.half}; };
    sweep_aabb_aabb(box(in.a.box), in.a.velocity, box(in.b.box), in.b.velocity, r);
  }
}

}  // namespace cc::harness
