// mesh_mesh_first's second opinions: FCL's BVHModel collision asked for one contact, one party
// per volume type (kinds/two_meshes.h).
#include "oracle/fcl/kinds/two_meshes.h"

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::MeshMeshFirstInput>>& fcl_parties() {
  static const std::vector<Party<harness::MeshMeshFirstInput>> parties =
      bvh_model_parties<harness::MeshMeshFirstInput>(true);
  return parties;
}

}  // namespace cc::fcl_oracle
