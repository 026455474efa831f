// ray_mesh's second opinions from Bullet: none wired yet: btBvhTriangleMeshShape::performRaycast
// is the counterpart.
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::RayMeshInput>>& bullet_parties() {
  static const std::vector<Party<harness::RayMeshInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
