// mesh_mesh_first's second opinions from Bullet: none wired yet: GImpact (btGImpactMeshShape) is
// the counterpart.
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::MeshMeshFirstInput>>& bullet_parties() {
  static const std::vector<Party<harness::MeshMeshFirstInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
