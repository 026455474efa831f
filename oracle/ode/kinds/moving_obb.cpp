// moving_obb's second opinions from ODE: none. ODE has no continuous collision test (its steps are discrete).
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {

template <>
const std::vector<Party<harness::MovingObbInput>>& ode_parties() {
  static const std::vector<Party<harness::MovingObbInput>> parties;
  return parties;
}

}  // namespace cc::ode_oracle
