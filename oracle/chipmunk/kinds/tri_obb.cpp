// tri_obb's second opinions from Chipmunk: none. Chipmunk is 2-D; the triangle and the box are 3-D.
#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {

template <>
const std::vector<Party<harness::TriObbInput>>& chipmunk_parties() {
  static const std::vector<Party<harness::TriObbInput>> parties;
  return parties;
}

}  // namespace cc::chipmunk_oracle
