// tri_aabb's second opinions from Bullet: none wired yet. The counterpart is GJK
// (btGjkPairDetector) on a btTriangleShape and a btBoxShape, whose collision margins and
// tolerances set its band; they are to be read first.
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::TriAabbInput>>& bullet_parties() {
  static const std::vector<Party<harness::TriAabbInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
