// sphere_sphere_distance's second opinions from Bullet: GJK (btGjkPairDetector with EPA) on two
// btSphereShapes, each a point with its radius as margin, with the points it reports; and
// btGjkEpaSolver2's signed distance of b's ball from a's shape, the distance alone.
#include <BulletCollision/CollisionShapes/btSphereShape.h>

#include "oracle/bullet/convert.h"
#include "oracle/bullet/gjk.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {
namespace {

using harness::SphereSphereDistanceInput;

btTransform at(const Vec3& center) {
  btTransform t;
  t.setIdentity();
  t.setOrigin(to_bullet(center));
  return t;
}

}  // namespace

template <>
const std::vector<Party<SphereSphereDistanceInput>>& bullet_parties() {
  static const std::vector<Party<SphereSphereDistanceInput>> parties = {
      {"bullet.btGjkPairDetector", kGjkDistanceBand,
       [](const SphereSphereDistanceInput& in) {
         const btSphereShape a(in.a.radius), b(in.b.radius);
         return distance_answer(gjk_closest(a, at(in.a.center), b, at(in.b.center)));
       }},
      {"bullet.btGjkEpaSolver2::SignedDistance", kEpaBand,
       [](const SphereSphereDistanceInput& in) {
         const btSphereShape a(in.a.radius);
         return epa_signed_distance(in.b.center, in.b.radius, a, at(in.a.center));
       }}};
  return parties;
}

}  // namespace cc::bullet_oracle
