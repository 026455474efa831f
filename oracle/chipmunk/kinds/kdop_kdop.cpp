// kdop_kdop's second opinions from Chipmunk: none. Chipmunk is 2-D and has no k-DOPs.
#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {

template <>
const std::vector<Party<harness::KdopKdopInput>>& chipmunk_parties() {
  static const std::vector<Party<harness::KdopKdopInput>> parties;
  return parties;
}

}  // namespace cc::chipmunk_oracle
