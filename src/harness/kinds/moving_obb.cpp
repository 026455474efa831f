// Generator for moving_obb: two boxes from the obb_obb generator (touching, nudged, parallel,
// degenerate), given velocities and moved back so that they meet at a chosen time of the step:
// 0, a quarter, a half or the end, or never; with equal velocities (no relative motion), equal
// velocity components (a rate of exactly 0 on an axis), and axis-aligned boxes with exact bounds.
#include <algorithm>
#include <cmath>

#include "harness/generation/shapes.h"

namespace cc::harness::detail {

namespace {

// Two boxes in the regimes of sweep_obb_obb's bound (those of test_obb_obb, with velocities up to
// 2^30 times the boxes' size), b slid so that the boxes meet, at an exact margin, at time tau.
MovingObbInput moving_pair_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  const ObbObbInput boxes = obb_pair_in_regime(v);
  const double size = std::max({max_abs(boxes.a.half), max_abs(boxes.b.half), 0x1p-20});
  MovingObbInput in{{boxes.a, {}}, {boxes.b, {}}};
  if (c.chance(70)) in.a.velocity = std::ldexp(size, v.small_int(30)) * draw_direction(v);
  in.b.velocity = c.chance(20) ? in.a.velocity : in.a.velocity + std::ldexp(size, v.small_int(30)) * draw_direction(v);
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

}  // namespace

MovingObbInput generate_moving_obb(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  if (c.chance(35)) return moving_pair_at_the_bound(v, options);
  ObbObbInput at_contact = generate_obb_obb(v, options);
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

}  // namespace cc::harness::detail
