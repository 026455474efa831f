// ray_aabb's second opinions from Chipmunk: none. Chipmunk is 2-D; the rays and boxes are 3-D.
#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {

template <>
const std::vector<Party<harness::RayAabbInput>>& chipmunk_parties() {
  static const std::vector<Party<harness::RayAabbInput>> parties;
  return parties;
}

}  // namespace cc::chipmunk_oracle
