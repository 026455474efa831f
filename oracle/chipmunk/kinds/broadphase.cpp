// broadphase's second opinions from Chipmunk: none. Chipmunk is 2-D: its spatial indexes hold 2-D boxes, these are 3-D.
#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {

template <>
const std::vector<Party<harness::BroadphaseInput>>& chipmunk_parties() {
  static const std::vector<Party<harness::BroadphaseInput>> parties;
  return parties;
}

}  // namespace cc::chipmunk_oracle
