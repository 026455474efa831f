// tri_tri's second opinions from Bullet: none. Bullet has no exact triangle-triangle test of its
// own (GImpact's triangle tests work with a collision margin); none is wired.
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::TriTriInput>>& bullet_parties() {
  static const std::vector<Party<harness::TriTriInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
