// mesh_mesh's second opinions: FCL's BVHModel collision with unlimited contacts, one party per
// volume type (kinds/two_meshes.h).
#include "oracle/fcl/kinds/two_meshes.h"

#include <stdexcept>

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::MeshMeshInput>>& fcl_parties() {
  static const std::vector<Party<harness::MeshMeshInput>> parties = bvh_model_parties<harness::MeshMeshInput>(false);
  return parties;
}

std::vector<std::string> fcl_mesh_parties() {
  std::vector<std::string> names;
  for (const ModelParty& p : model_parties()) names.push_back(p.name);
  return names;
}

// Every model, whatever the library's hierarchy: the commands compare hierarchies.
Opinion fcl_collide_meshes(const std::string& party, const harness::MeshPair& m) {
  for (const ModelParty& p : model_parties()) {
    if (p.name != party) continue;
    Opinion o = fcl_collide_models(p.volume, m, false);
    o.party = p.name;
    o.band = p.band;
    return o;
  }
  throw std::out_of_range("no mesh party " + party);
}

}  // namespace cc::fcl_oracle
