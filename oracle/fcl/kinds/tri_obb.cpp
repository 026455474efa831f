// tri_obb's second opinion: FCL's GJKSolver_libccd::shapeTriangleIntersect with a Box shape.
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::TriObbInput>>& fcl_parties() {
  static const std::vector<Party<harness::TriObbInput>> parties = {
      {"fcl.shapeTriangleIntersect", {0x1p-18, BandSides::two_sided, 0, "libccd MPR with FCL's gjk_default_tolerance 1e-6, absolute"},
       [](const harness::TriObbInput& in) { return fcl_shape_triangle(in.box.half, in.box.axes, in.box.center, in.tri); }}};
  return parties;
}

}  // namespace cc::fcl_oracle
