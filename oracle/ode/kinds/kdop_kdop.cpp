// kdop_kdop's second opinions from ODE: none. ODE has no k-DOPs.
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {

template <>
const std::vector<Party<harness::KdopKdopInput>>& ode_parties() {
  static const std::vector<Party<harness::KdopKdopInput>> parties;
  return parties;
}

}  // namespace cc::ode_oracle
