// disc_walls's second opinions: none. FCL and libccd are 3-D: a disc as a cylinder (or a sphere)
// against a wall as a flat box or a capsule would test their GJK and MPR tolerances (about 1e-6,
// absolute) and the 3-D stand-in, not the maze's 2-D test; no party of theirs answers a disc
// against segments fairly. The exact reference and the library's other method (its unit's
// library party, the centre against the walls grown by the radius) are the other two opinions.
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::DiscWallsInput>>& fcl_parties() {
  static const std::vector<Party<harness::DiscWallsInput>> parties;
  return parties;
}

}  // namespace cc::fcl_oracle
