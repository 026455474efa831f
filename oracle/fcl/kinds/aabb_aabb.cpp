// aabb_aabb's second opinion: FCL's AABBd::overlap.
#include <fcl/math/bv/AABB.h>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::AabbAabbInput>>& fcl_parties() {
  static const std::vector<Party<harness::AabbAabbInput>> parties = {
      {"fcl.AABBd::overlap", {0, BandSides::exact, 0, "comparisons of inputs only: exact"},
       [](const harness::AabbAabbInput& in) {
         const fcl::AABBd a(to_fcl(in.a.lo), to_fcl(in.a.hi)), b(to_fcl(in.b.lo), to_fcl(in.b.hi));
         return answered(a.overlap(b));
       }}};
  return parties;
}

}  // namespace cc::fcl_oracle
