// tri_aabb's second opinion from Bullet: GJK (btGjkPairDetector with EPA) on a btTriangleShape
// and a btBoxShape of the box's centre and half extents (rounded to nearest), margins 0; a hit
// when it reports a distance <= 0 (gjk.h; its band: absolute tolerances about 1e-3).
#include "oracle/bullet/gjk.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::TriAabbInput>>& bullet_parties() {
  static const std::vector<Party<harness::TriAabbInput>> parties = {
      {"bullet.btGjkPairDetector", kGjkBand, [](const harness::TriAabbInput& in) {
         const Vec3 center = 0.5 * (in.box.lo + in.box.hi), half = 0.5 * (in.box.hi - in.box.lo);
         return gjk_triangle_box(in.tri, half, Mat3::identity(), center);
       }}};
  return parties;
}

}  // namespace cc::bullet_oracle
