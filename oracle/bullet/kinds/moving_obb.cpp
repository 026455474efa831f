// moving_obb's second opinion from Bullet, as a user of its continuous collision asks it: a
// discrete test at the start of the step (GJK with EPA, btGjkPairDetector: a hit when the
// distance it reports is <= 0), then, for boxes apart at the start, btGjkConvexCast over the
// step (the boxes translated by their velocities; a first contact at a fraction in [0, 1]).
// Both on btBoxShapes with frames made proper and a collision margin m of 2^-30 of the case's
// scale (the largest magnitude of the centres, half extents and velocities), the half extents
// less m kept as implicit dimensions (at least 0): Bullet's GJK needs a margin (with none the
// cast reports nothing, even for two unit boxes meeting head on), and this one rounds the
// boxes' edges by m, or grows a flat box by m, far below the band. The cast advances until GJK's
// distance is at most 0.001 (absolute) and answers a contact only for boxes approaching each
// other there; with GJK's own absolute tolerances, about 1e-3 at unit scale: 2^-9 two-sided.
// No time is compared.
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkConvexCast.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <algorithm>
#include <cmath>

#include "oracle/bullet/convert.h"
#include "oracle/bullet/gjk.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {
namespace {

// The box less the margin m, with the margin m: the box with its edges rounded by m.
void set_with_margin(btBoxShape& shape, const Vec3& half, double m) {
  shape.setMargin(m);
  shape.setImplicitShapeDimensions({std::max(half.x - m, 0.0), std::max(half.y - m, 0.0), std::max(half.z - m, 0.0)});
}

Opinion start_test_then_convex_cast(const harness::MovingObbInput& in) {
  double scale = 0;
  for (const MovingObb* m : {&in.a, &in.b}) {
    scale = std::max({scale, max_abs(m->box.center), max_abs(m->box.half), max_abs(m->velocity)});
  }
  if (!std::isfinite(scale)) return not_applicable("a NaN or infinite input");
  const double margin = scale > 0 ? std::ldexp(scale, -30) : 0x1p-1000;
  btBoxShape box_a({1, 1, 1}), box_b({1, 1, 1});
  set_with_margin(box_a, in.a.box.half, margin), set_with_margin(box_b, in.b.box.half, margin);
  const btTransform a0 = placement(in.a.box.axes, in.a.box.center), b0 = placement(in.b.box.axes, in.b.box.center);
  btTransform a1 = a0, b1 = b0;
  a1.setOrigin(a0.getOrigin() + to_bullet(in.a.velocity));
  b1.setOrigin(b0.getOrigin() + to_bullet(in.b.velocity));
  if (const std::optional<double> start = gjk_distance(box_a, a0, box_b, b0); start && *start <= 0) return answered(true);
  btVoronoiSimplexSolver simplex;
  btGjkConvexCast convex_cast(&box_a, &box_b, &simplex);
  btConvexCast::CastResult result;
  return answered(convex_cast.calcTimeOfImpact(a0, a1, b0, b1, result) && result.m_fraction >= 0 && result.m_fraction <= 1);
}

}  // namespace

template <>
const std::vector<Party<harness::MovingObbInput>>& bullet_parties() {
  static const std::vector<Party<harness::MovingObbInput>> parties = {
      {"bullet.btGjkConvexCast",
       {0x1p-9, BandSides::two_sided, 0,
        "GJK at the start, then a cast to a distance of 0.001 (absolute): about 1e-3 at unit scale; margins 2^-30 of the scale"},
       start_test_then_convex_cast}};
  return parties;
}

}  // namespace cc::bullet_oracle
