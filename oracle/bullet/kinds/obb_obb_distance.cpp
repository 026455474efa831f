// obb_obb_distance's second opinion from Bullet: GJK (btGjkPairDetector with EPA where they
// overlap) on two btBoxShapes of margin 0, with the points it reports.
#include <BulletCollision/CollisionShapes/btBoxShape.h>

#include "oracle/bullet/convert.h"
#include "oracle/bullet/gjk.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {
using harness::ObbObbDistanceInput;

template <>
const std::vector<Party<ObbObbDistanceInput>>& bullet_parties() {
  static const std::vector<Party<ObbObbDistanceInput>> parties = {
      {"bullet.btGjkPairDetector", kGjkDistanceBand, [](const ObbObbDistanceInput& in) {
         btBoxShape a({1, 1, 1}), b({1, 1, 1});
         set_half_extents(a, in.a.half);
         set_half_extents(b, in.b.half);
         return distance_answer(gjk_closest(a, placement(in.a.axes, in.a.center), b, placement(in.b.axes, in.b.center)));
       }}};
  return parties;
}

}  // namespace cc::bullet_oracle
