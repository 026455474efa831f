// broadphase's second opinions from Bullet: none wired yet: btAxisSweep3 and btDbvtBroadphase,
// driven frame by frame, are the counterparts.
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::BroadphaseInput>>& bullet_parties() {
  static const std::vector<Party<harness::BroadphaseInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
