// sphere_sphere's second opinion: FCL's collide() on two Sphere shapes.
#include <fcl/geometry/shape/sphere.h>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/fcl_shapes.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::SphereSphereInput>>& fcl_parties() {
  static const std::vector<Party<harness::SphereSphereInput>> parties = {
      {"fcl.collide(Sphere,Sphere)", {0x1p-48, BandSides::two_sided, 0, "|c_a - c_b| > r_a + r_b in floating point, no tolerance"},
       [](const harness::SphereSphereInput& in) {
         const fcl::Sphered a(in.a.radius), b(in.b.radius);
         return answered(fcl_collide(a, to_fcl_transform(Mat3::identity(), in.a.center), b,
                                     to_fcl_transform(Mat3::identity(), in.b.center)));
       }}};
  return parties;
}

}  // namespace cc::fcl_oracle
