// kdop_kdop's second opinions from Bullet: none: Bullet has no k-DOPs.
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::KdopKdopInput>>& bullet_parties() {
  static const std::vector<Party<harness::KdopKdopInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
