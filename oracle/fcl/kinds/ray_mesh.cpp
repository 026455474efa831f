// ray_mesh's second opinions: none. FCL 0.7 casts no rays; the exact reference and the
// library's brute force (its unit's library party) are the other two opinions.
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::RayMeshInput>>& fcl_parties() {
  static const std::vector<Party<harness::RayMeshInput>> parties;
  return parties;
}

}  // namespace cc::fcl_oracle
