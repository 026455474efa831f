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
         const std::optional<GjkClosest> c =
             gjk_closest(ball, placement(Mat3::identity(), in.ball.center), box, placement(in.box.axes, in.box.center));
         if (!c) return harness::failed("GJK reported no distance");
         harness::Answer answer = harness::Answer::of(c->distance <= 0);
         answer.params = {c->distance, c->on_a.x, c->on_a.y, c->on_a.z, c->on_b.x, c->on_b.y, c->on_b.z};
         return harness::answered(answer);
       }},
      {"bullet.btGjkEpaSolver2::SignedDistance", kEpaBand,
       [](const SphereObbDistanceInput& in) {
         btBoxShape box({1, 1, 1});
         set_half_extents(box, in.box.half);
         const std::optional<double> d = epa_signed_distance(in.ball.center, in.ball.radius, box, placement(in.box.axes, in.box.center));
         if (!d) return harness::failed("GJK and EPA reported no distance");
         harness::Answer answer = harness::Answer::of(*d <= 0);
         answer.params = {*d};
         return harness::answered(answer);
       }}};
  return parties;
}

}  // namespace cc::bullet_oracle
