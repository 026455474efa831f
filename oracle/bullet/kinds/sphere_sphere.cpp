// sphere_sphere's second opinions from Bullet: none wired yet. The counterpart is
// btSphereSphereCollisionAlgorithm (the distance of the centres, a square root, against the sum of
// the radii), reached through a collision world and its dispatcher; its band is to be read from
// that code first.
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::SphereSphereInput>>& bullet_parties() {
  static const std::vector<Party<harness::SphereSphereInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
