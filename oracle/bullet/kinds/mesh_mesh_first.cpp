// mesh_mesh_first's second opinion from Bullet: GImpact on the two placed meshes (the first contact; gimpact.h).
#include "oracle/bullet/gimpact.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::MeshMeshFirstInput>>& bullet_parties() {
  static const std::vector<Party<harness::MeshMeshFirstInput>> parties = {
      {"bullet.btGImpactCollisionAlgorithm", kGImpactBand,
       [](const harness::MeshMeshFirstInput& in) { return gimpact_collide(in.meshes, true); }}};
  return parties;
}

}  // namespace cc::bullet_oracle
