// Generator for moving_obb: two boxes from the obb_obb generator (touching, nudged, parallel,
// degenerate), given velocities and moved back so that they meet at a chosen time of the step:
// 0, a quarter, a half or the end, or never; with equal velocities (no relative motion), equal
// velocity components (a rate of exactly 0 on an axis), and axis-aligned boxes with exact bounds.
#include <cmath>

#include "harness/generate_detail.h"

namespace cc::harness::detail {

MovingObbInput generate_moving_obb(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
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
