// tri_obb_distance's second opinion from Bullet: GJK (btGjkPairDetector with EPA where they
// overlap) on a btTriangleShape and a btBoxShape, margins 0, with the points it reports.
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>

#include "oracle/bullet/convert.h"
#include "oracle/bullet/gjk.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {
using harness::TriObbDistanceInput;

template <>
const std::vector<Party<TriObbDistanceInput>>& bullet_parties() {
  static const std::vector<Party<TriObbDistanceInput>> parties = {
      {"bullet.btGjkPairDetector", kGjkDistanceBand, [](const TriObbDistanceInput& in) {
         btTriangleShape t(to_bullet(in.tri.v[0]), to_bullet(in.tri.v[1]), to_bullet(in.tri.v[2]));
         t.setMargin(0);
         btBoxShape box({1, 1, 1});
         set_half_extents(box, in.box.half);
         btTransform identity;
         identity.setIdentity();
         return distance_answer(gjk_closest(t, identity, box, placement(in.box.axes, in.box.center)));
       }}};
  return parties;
}

}  // namespace cc::bullet_oracle
