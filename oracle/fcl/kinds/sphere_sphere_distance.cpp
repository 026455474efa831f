// sphere_sphere_distance's second opinions: FCL's distance() on two Sphere shapes with nearest
// points, asked three ways. Unsigned (its default, libccd's solver): sphereSphereDistance, closed
// form, which gives -1 and no points for balls that meet. Signed with libccd's solver: libccd's
// GJK and, for balls that meet, its EPA, whose tolerance (1e-6) is absolute. Signed with the indep
// solver: the closed form apart, and where the balls meet minus the depth of collide()'s contact,
// its points not on the spheres (judged on the distance alone).
#include <fcl/geometry/shape/sphere.h>

#include <cmath>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/fcl_shapes.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {
namespace {

using harness::SphereSphereDistanceInput;

Opinion distance_of(const SphereSphereDistanceInput& in, FclDistanceRequest how) {
  if (!finite(in.a.center) || !finite(in.b.center) || !std::isfinite(in.a.radius) || !std::isfinite(in.b.radius)) {
    return not_applicable("a NaN or infinite number, on which libccd reads memory it never set");
  }
  const fcl::Sphered a(in.a.radius), b(in.b.radius);
  return fcl_distance(a, to_fcl_transform(Mat3::identity(), in.a.center), b, to_fcl_transform(Mat3::identity(), in.b.center),
                      how);
}

}  // namespace

template <>
const std::vector<Party<SphereSphereDistanceInput>>& fcl_parties() {
  static const std::vector<Party<SphereSphereDistanceInput>> parties = {
      {"fcl.distance(Sphere,Sphere)", kClosedFormDistanceBand,
       [](const SphereSphereDistanceInput& in) { return distance_of(in, {false, false}); }},
      {"fcl.distance(Sphere,Sphere,signed,libccd)", kGjkDistanceBand,
       [](const SphereSphereDistanceInput& in) { return distance_of(in, {false, true}); }},
      {"fcl.distance(Sphere,Sphere,signed,indep)", kClosedFormDistanceBand,
       [](const SphereSphereDistanceInput& in) { return distance_of(in, {true, true}); }}};
  return parties;
}

}  // namespace cc::fcl_oracle
