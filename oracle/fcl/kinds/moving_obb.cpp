// moving_obb's second opinion: FCL's continuousCollide by conservative advancement on two boxes under
// translation, as a second opinion on whether they meet during the step.
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/continuous_collision.h>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/parties.h"
#include "oracle/fcl/time_limit.h"

namespace cc::fcl_oracle {
namespace {

Opinion fcl_continuous_collide(const harness::MovingObbInput& in) {
  for (const MovingObb* m : {&in.a, &in.b}) {
    if (m->box.half.x <= 0 || m->box.half.y <= 0 || m->box.half.z <= 0) {
      return not_applicable("a box with a zero extent (FCL's Box needs positive sides)");
    }
  }
  const fcl::Boxd a(2 * in.a.box.half.x, 2 * in.a.box.half.y, 2 * in.a.box.half.z);
  const fcl::Boxd b(2 * in.b.box.half.x, 2 * in.b.box.half.y, 2 * in.b.box.half.z);
  const fcl::Transform3d a0 = to_fcl_transform(in.a.box.axes, in.a.box.center);
  const fcl::Transform3d a1 = to_fcl_transform(in.a.box.axes, in.a.box.center + in.a.velocity);
  const fcl::Transform3d b0 = to_fcl_transform(in.b.box.axes, in.b.box.center);
  const fcl::Transform3d b1 = to_fcl_transform(in.b.box.axes, in.b.box.center + in.b.velocity);
  fcl::ContinuousCollisionRequestd request;
  request.ccd_motion_type = fcl::CCDM_TRANS;
  request.ccd_solver_type = fcl::CCDC_CONSERVATIVE_ADVANCEMENT;
  request.gjk_solver_type = fcl::GST_LIBCCD;
  fcl::ContinuousCollisionResultd result;
  const Guarded outcome =
      run_guarded(kLibccdTimeLimit * 10, [&] { fcl::continuousCollide(&a, a0, a1, &b, b0, b1, request, result); });
  if (outcome == Guarded::timed_out) return timed_out("did not return within its time limit");
  if (outcome == Guarded::aborted) return failed("aborted (a failed assertion in FCL's libccd code)");
  return answered(result.is_collide);
}

}  // namespace

template <>
const std::vector<Party<harness::MovingObbInput>>& fcl_parties() {
  static const std::vector<Party<harness::MovingObbInput>> parties = {
      {"fcl.continuousCollide",
       {0x1p-12, BandSides::two_sided, 0,
        "conservative advancement stops within toc_err = 1e-4 of the step and GJK's 1e-6 distance tolerance, "
        "absolute: the band they mean at unit scale"},
       fcl_continuous_collide}};
  return parties;
}

}  // namespace cc::fcl_oracle
