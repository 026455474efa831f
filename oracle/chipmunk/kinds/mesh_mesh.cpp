// mesh_mesh's second opinions from Chipmunk: none. Chipmunk is 2-D and has no triangle meshes.
#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {

template <>
const std::vector<Party<harness::MeshMeshInput>>& chipmunk_parties() {
  static const std::vector<Party<harness::MeshMeshInput>> parties;
  return parties;
}

}  // namespace cc::chipmunk_oracle
