// sphere_sphere's second opinion from Bullet: btSphereSphereCollisionAlgorithm, the algorithm its
// default collision configuration gives two btSphereShapes, run by btCollisionWorld::contactPairTest
// (the two objects are not added to the world, nor paired by it). It reports a contact
// unless len > r_a + r_b, len the square root of the rounded squares of the rounded difference of
// the centres: within about 4u of the distance, and the sum of the radii within u, so a
// misjudged case lies within 5u of (len + r_a + r_b), at most 2^-47 of the scale (the centres'
// distance reaching 2 sqrt 3 scales); a difference whose squares underflow reads as 0 and is
// beyond any band, a defect of Bullet's.
#include <BulletCollision/CollisionShapes/btSphereShape.h>

#include "oracle/bullet/collision_world.h"
#include "oracle/bullet/convert.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {
namespace {

struct AnyContact final : btCollisionWorld::ContactResultCallback {
  bool any = false;
  btScalar addSingleResult(btManifoldPoint&, const btCollisionObjectWrapper*, int, int, const btCollisionObjectWrapper*,
                           int, int) override {
    any = true;
    return 0;
  }
};

Opinion contact_pair_test(const harness::SphereSphereInput& in) {
  btSphereShape shape_a(in.a.radius), shape_b(in.b.radius);
  btCollisionObject a, b;
  a.setCollisionShape(&shape_a), b.setCollisionShape(&shape_b);
  btTransform place;
  place.setIdentity();
  place.setOrigin(to_bullet(in.a.center));
  a.setWorldTransform(place);
  place.setOrigin(to_bullet(in.b.center));
  b.setWorldTransform(place);
  AnyContact contact;
  collision_world().contactPairTest(&a, &b, contact);
  return answered(contact.any);
}

}  // namespace

template <>
const std::vector<Party<harness::SphereSphereInput>>& bullet_parties() {
  static const std::vector<Party<harness::SphereSphereInput>> parties = {
      {"bullet.btSphereSphereCollisionAlgorithm",
       {0x1p-47, BandSides::two_sided, 0,
        "the centres' distance as a square root of rounded squares (4u) against the rounded sum of the radii (u)"},
       contact_pair_test}};
  return parties;
}

}  // namespace cc::bullet_oracle
