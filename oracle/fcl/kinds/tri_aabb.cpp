// tri_aabb's second opinion: FCL's GJKSolver_libccd::shapeTriangleIntersect with a Box shape.
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::TriAabbInput>>& fcl_parties() {
  static const std::vector<Party<harness::TriAabbInput>> parties = {
      {"fcl.shapeTriangleIntersect", {0x1p-18, BandSides::two_sided, 0, "libccd MPR with FCL's gjk_default_tolerance 1e-6, absolute"},
       [](const harness::TriAabbInput& in) {
         // FCL has no AABB shape: the box of the same centre and size, rounded to nearest.
         const Vec3 center = 0.5 * (in.box.lo + in.box.hi), half = 0.5 * (in.box.hi - in.box.lo);
         return fcl_shape_triangle(half, Mat3::identity(), center, in.tri);
       }}};
  return parties;
}

}  // namespace cc::fcl_oracle
