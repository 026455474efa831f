// sphere_obb_distance's second opinions: FCL's distance() on a Sphere and a Box (placed by the
// box's axes, made proper, and centre) with nearest points, asked three ways. Unsigned (its
// default, libccd's solver): sphereBoxDistance, closed form, which gives -1 and no points where
// the ball meets the box. Signed with libccd's solver: libccd's GJK and, where they meet, its EPA,
// whose tolerance (1e-6) is absolute. Signed with the indep solver: the closed form apart, and
// where they meet minus the depth of collide()'s contact (sphereBoxIntersect), its points not on
// the shapes (judged on the distance alone).
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/sphere.h>

#include <cmath>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/fcl_shapes.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {
namespace {

using harness::SphereObbDistanceInput;

Opinion distance_of(const SphereObbDistanceInput& in, FclDistanceRequest how) {
  bool all_finite = finite(in.ball.center) && std::isfinite(in.ball.radius) && finite(in.box.center) && finite(in.box.half);
  for (const Vec3& axis : in.box.axes.col) all_finite = all_finite && finite(axis);
  if (!all_finite) return not_applicable("a NaN or infinite number, on which libccd reads memory it never set");
  const fcl::Sphered ball(in.ball.radius);
  const fcl::Boxd box(2 * in.box.half.x, 2 * in.box.half.y, 2 * in.box.half.z);
  return fcl_distance(ball, to_fcl_transform(Mat3::identity(), in.ball.center), box,
                      to_fcl_transform(in.box.axes, in.box.center), how);
}

}  // namespace

template <>
const std::vector<Party<SphereObbDistanceInput>>& fcl_parties() {
  static const std::vector<Party<SphereObbDistanceInput>> parties = {
      {"fcl.distance(Sphere,Box)", kClosedFormDistanceBand,
       [](const SphereObbDistanceInput& in) { return distance_of(in, {false, false}); }},
      {"fcl.distance(Sphere,Box,signed,libccd)", kGjkDistanceBand,
       [](const SphereObbDistanceInput& in) { return distance_of(in, {false, true}); }},
      {"fcl.distance(Sphere,Box,signed,indep)", kClosedFormDistanceBand,
       [](const SphereObbDistanceInput& in) { return distance_of(in, {true, true}); }}};
  return parties;
}

}  // namespace cc::fcl_oracle
