// obb_obb's second opinions: FCL's OBBd::overlap, and collide() on two Box shapes.
#include <fcl/geometry/shape/box.h>
#include <fcl/math/bv/OBB.h>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/fcl_shapes.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::ObbObbInput>>& fcl_parties() {
  static const std::vector<Party<harness::ObbObbInput>> parties = {
      {"fcl.OBBd::overlap",
       {0x1p-17, BandSides::two_sided, 0, "obbDisjoint adds 1e-6 to every |R_ij|: up to 4e-6 of the extents"},
       [](const harness::ObbObbInput& in) { return answered(to_fcl_obb(in.a).overlap(to_fcl_obb(in.b))); }},
      {"fcl.collide(Box,Box)",
       {0x1p-40, BandSides::two_sided, 0, "ODE's boxBox2: |R_ij| padded by 10 eps max(extent, 1); otherwise rounding only"},
       [](const harness::ObbObbInput& in) {
         const fcl::Boxd a(2 * in.a.half.x, 2 * in.a.half.y, 2 * in.a.half.z);
         const fcl::Boxd b(2 * in.b.half.x, 2 * in.b.half.y, 2 * in.b.half.z);
         return answered(
             fcl_collide(a, to_fcl_transform(in.a.axes, in.a.center), b, to_fcl_transform(in.b.axes, in.b.center)));
       }}};
  return parties;
}

}  // namespace cc::fcl_oracle
