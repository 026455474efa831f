// tri_aabb's second opinions from ODE: none wired yet (ODE's trimesh-box collider would be one: a
// one-triangle dTriMesh against a dBox).
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {

template <>
const std::vector<Party<harness::TriAabbInput>>& ode_parties() {
  static const std::vector<Party<harness::TriAabbInput>> parties;
  return parties;
}

}  // namespace cc::ode_oracle
