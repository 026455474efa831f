// disc_walls's second opinions from Bullet: none: Bullet is 3-D (see
// oracle/fcl/kinds/disc_walls.cpp: a 3-D stand-in would test it, not the maze).
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::DiscWallsInput>>& bullet_parties() {
  static const std::vector<Party<harness::DiscWallsInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
