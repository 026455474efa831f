// tri_tri_intersection's second opinions from Chipmunk: none. Chipmunk is 2-D; the triangles are 3-D.
#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {

template <>
const std::vector<Party<harness::TriTriIntersectionInput>>& chipmunk_parties() {
  static const std::vector<Party<harness::TriTriIntersectionInput>> parties;
  return parties;
}

}  // namespace cc::chipmunk_oracle
