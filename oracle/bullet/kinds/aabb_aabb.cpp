// aabb_aabb's second opinion from Bullet: TestAabbAgainstAabb2 (LinearMath/btAabbUtil2.h), the
// test its broadphases (btDbvt, btAxisSweep3's pair checks) apply to two boxes: comparisons of
// the inputs only, closed (touching overlaps), so exact.
#include <LinearMath/btAabbUtil2.h>

#include "oracle/bullet/convert.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::AabbAabbInput>>& bullet_parties() {
  static const std::vector<Party<harness::AabbAabbInput>> parties = {
      {"bullet.TestAabbAgainstAabb2", {0, BandSides::exact, 0, "comparisons of inputs only: exact"},
       [](const harness::AabbAabbInput& in) {
         return answered(TestAabbAgainstAabb2(to_bullet(in.a.lo), to_bullet(in.a.hi), to_bullet(in.b.lo), to_bullet(in.b.hi)));
       }}};
  return parties;
}

}  // namespace cc::bullet_oracle
