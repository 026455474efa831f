// tri_tri_intersection's second opinions from ODE: none. ODE's triangle contacts are points for
// dynamics, not the intersection.
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {

template <>
const std::vector<Party<harness::TriTriIntersectionInput>>& ode_parties() {
  static const std::vector<Party<harness::TriTriIntersectionInput>> parties;
  return parties;
}

}  // namespace cc::ode_oracle
