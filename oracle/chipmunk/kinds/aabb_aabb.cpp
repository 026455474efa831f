// aabb_aabb's second opinions from Chipmunk: none. Chipmunk is 2-D; the boxes are 3-D.
#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {

template <>
const std::vector<Party<harness::AabbAabbInput>>& chipmunk_parties() {
  static const std::vector<Party<harness::AabbAabbInput>> parties;
  return parties;
}

}  // namespace cc::chipmunk_oracle
