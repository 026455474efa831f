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
         const std::optional<GjkClosest> c = gjk_closest(a, at(in.a.center), b, at(in.b.center));
         if (!c) return harness::failed("GJK reported no distance");
         harness::Answer answer = harness::Answer::of(c->distance <= 0);
         answer.params = {c->distance, c->on_a.x, c->on_a.y, c->on_a.z, c->on_b.x, c->on_b.y, c->on_b.z};
         return harness::answered(answer);
       }},
      {"bullet.btGjkEpaSolver2::SignedDistance", kEpaBand,
       [](const SphereSphereDistanceInput& in) {
         const btSphereShape a(in.a.radius);
         const std::optional<double> d = epa_signed_distance(in.b.center, in.b.radius, a, at(in.a.center));
         if (!d) return harness::failed("GJK and EPA reported no distance");
         harness::Answer answer = harness::Answer::of(*d <= 0);
         answer.params = {*d};
         return harness::answered(answer);
       }}};
  return parties;
}

}  // namespace cc::bullet_oracle
