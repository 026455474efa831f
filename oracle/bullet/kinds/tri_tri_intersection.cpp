// tri_tri_intersection's second opinions from Bullet: none (Bullet has no exact triangle-triangle
// test; GImpact's triangle contacts work with a collision margin).
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::TriTriIntersectionInput>>& bullet_parties() {
  static const std::vector<Party<harness::TriTriIntersectionInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
