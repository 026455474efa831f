// mesh_mesh's second opinions from ODE: none. ODE's trimesh-trimesh collider reports contacts for
// dynamics, not the pairs of triangles that meet: contacts of different pairs whose points fall
// in the same cell of a 1e-4 grid (absolute) and whose depths differ by at most 1e-5 are merged
// into one naming a single pair (or none), and a pair's contact points are only its deepest ones.
// The set of pairs it reports is a subset of those it finds colliding by design, so the
// all-pairs comparison would count every merged pair as a miss. The first-hit kind asks it (any
// pair it names must collide).
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {

template <>
const std::vector<Party<harness::MeshMeshInput>>& ode_parties() {
  static const std::vector<Party<harness::MeshMeshInput>> parties;
  return parties;
}

}  // namespace cc::ode_oracle
