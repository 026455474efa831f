// disc_walls's second opinions from ODE: none. ODE's geoms are 3-D (see oracle/fcl/kinds/disc_walls.cpp).
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {

template <>
const std::vector<Party<harness::DiscWallsInput>>& ode_parties() {
  static const std::vector<Party<harness::DiscWallsInput>> parties;
  return parties;
}

}  // namespace cc::ode_oracle
