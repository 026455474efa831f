// sphere_sphere's second opinions from Chipmunk: none. Chipmunk is 2-D; the spheres are 3-D.
#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {

template <>
const std::vector<Party<harness::SphereSphereInput>>& chipmunk_parties() {
  static const std::vector<Party<harness::SphereSphereInput>> parties;
  return parties;
}

}  // namespace cc::chipmunk_oracle
