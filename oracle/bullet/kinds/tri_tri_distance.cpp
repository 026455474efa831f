// tri_tri_distance's second opinion from Bullet: GJK (btGjkPairDetector with EPA) on two
// btTriangleShapes, margins 0, with the points it reports. Where it reports a penetration (a
// distance < 0: two flat shapes have none) only its hit is judged.
#include <BulletCollision/CollisionShapes/btTriangleShape.h>

#include "oracle/bullet/convert.h"
#include "oracle/bullet/gjk.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

template <>
const std::vector<Party<harness::TriTriDistanceInput>>& bullet_parties() {
  static const std::vector<Party<harness::TriTriDistanceInput>> parties = {
      {"bullet.btGjkPairDetector", kGjkDistanceBand,
       [](const harness::TriTriDistanceInput& in) {
         btTriangleShape a(to_bullet(in.a.v[0]), to_bullet(in.a.v[1]), to_bullet(in.a.v[2]));
         btTriangleShape b(to_bullet(in.b.v[0]), to_bullet(in.b.v[1]), to_bullet(in.b.v[2]));
         a.setMargin(0);
         b.setMargin(0);
         btTransform identity;
         identity.setIdentity();
         const std::optional<GjkClosest> c = gjk_closest(a, identity, b, identity);
         if (!c) return harness::failed("GJK reported no distance");
         harness::Answer answer = harness::Answer::of(c->distance <= 0);
         if (c->distance >= 0) {
           answer.params = {c->distance, c->on_a.x, c->on_a.y, c->on_a.z, c->on_b.x, c->on_b.y, c->on_b.z};
         }
         return harness::answered(answer);
       }}};
  return parties;
}

}  // namespace cc::bullet_oracle
