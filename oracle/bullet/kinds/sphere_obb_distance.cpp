// sphere_obb_distance's second opinions from Bullet: GJK (btGjkPairDetector with EPA) on a
// btSphereShape (a point with its radius as margin) and a btBoxShape of margin 0, with the points
// it reports; and btGjkEpaSolver2's signed distance of the ball from the box, the distance alone.
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>

#include "oracle/bullet/convert.h"
#include "oracle/bullet/gjk.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {
using harness::SphereObbDistanceInput;

template <>
const std::vector<Party<SphereObbDistanceInput>>& bullet_parties() {
  static const std::vector<Party<SphereObbDistanceInput>> parties = {
      {"bullet.btGjkPairDetector", kGjkDistanceBand,
       [](const SphereObbDistanceInput& in) {
         const btSphereShape ball(in.ball.radius);
         btBoxShape box({1, 1, 1});
         set_half_extents(box, in.box.half);
         return distance_answer(
             gjk_closest(ball, placement(Mat3::identity(), in.ball.center), box, placement(in.box.axes, in.box.center)));
       }},
      {"bullet.btGjkEpaSolver2::SignedDistance", kEpaBand,
       [](const SphereObbDistanceInput& in) {
         btBoxShape box({1, 1, 1});
         set_half_extents(box, in.box.half);
         return epa_signed_distance(in.ball.center, in.ball.radius, box, placement(in.box.axes, in.box.center));
       }}};
  return parties;
}

}  // namespace cc::bullet_oracle
