// moving_obb's second opinions from Bullet: none wired yet: btContinuousConvexCollision or
// btGjkConvexCast are the counterparts.
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::MovingObbInput>>& bullet_parties() {
  static const std::vector<Party<harness::MovingObbInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
