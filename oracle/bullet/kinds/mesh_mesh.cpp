// mesh_mesh's second opinions from Bullet: none wired yet: GImpact (btGImpactMeshShape) against
// GImpact is the counterpart.
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::MeshMeshInput>>& bullet_parties() {
  static const std::vector<Party<harness::MeshMeshInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
