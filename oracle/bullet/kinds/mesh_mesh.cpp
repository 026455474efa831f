// mesh_mesh's second opinion from Bullet: GImpact on the two placed meshes (every contact; gimpact.h).
#include "oracle/bullet/gimpact.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::MeshMeshInput>>& bullet_parties() {
  static const std::vector<Party<harness::MeshMeshInput>> parties = {
      {"bullet.btGImpactCollisionAlgorithm", kGImpactBand,
       [](const harness::MeshMeshInput& in) { return gimpact_collide(in.meshes, false); }}};
  return parties;
}

}  // namespace cc::bullet_oracle
