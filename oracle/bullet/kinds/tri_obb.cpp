// tri_obb's second opinion from Bullet: GJK (btGjkPairDetector with EPA) on a btTriangleShape
// and a btBoxShape placed by the box's frame (made proper) and centre, margins 0; a hit when it
// reports a distance <= 0 (gjk.h; its band: absolute tolerances about 1e-3).
#include "oracle/bullet/gjk.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::TriObbInput>>& bullet_parties() {
  static const std::vector<Party<harness::TriObbInput>> parties = {
      {"bullet.btGjkPairDetector", kGjkBand, [](const harness::TriObbInput& in) {
         return gjk_triangle_box(in.tri, in.box.half, in.box.axes, in.box.center);
       }}};
  return parties;
}

}  // namespace cc::bullet_oracle
