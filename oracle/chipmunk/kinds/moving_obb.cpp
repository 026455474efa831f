// moving_obb's second opinions from Chipmunk: none. Chipmunk is 2-D; the boxes are 3-D.
#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {

template <>
const std::vector<Party<harness::MovingObbInput>>& chipmunk_parties() {
  static const std::vector<Party<harness::MovingObbInput>> parties;
  return parties;
}

}  // namespace cc::chipmunk_oracle
