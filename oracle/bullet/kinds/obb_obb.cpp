// obb_obb's second opinions from Bullet: none wired yet. The counterpart is btBoxBoxDetector (a
// port of ODE's box-box test, which reports contacts with a depth); its band is to be read from
// that code first.
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::ObbObbInput>>& bullet_parties() {
  static const std::vector<Party<harness::ObbObbInput>> parties;
  return parties;
}

}  // namespace cc::bullet_oracle
