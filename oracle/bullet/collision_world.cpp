#include "oracle/bullet/collision_world.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>

namespace cc::bullet_oracle {
namespace {

struct World {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase pairs;  // a world needs one; contactPairTest does not use it
  btCollisionWorld world{&dispatcher, &pairs, &configuration};
  btGImpactCollisionAlgorithm::CreateFunc gimpact;
  World() {
    btGImpactCollisionAlgorithm::registerAlgorithm(&dispatcher);
    for (int other = 0; other < MAX_BROADPHASE_COLLISION_TYPES; ++other) {
      dispatcher.registerClosestPointsCreateFunc(GIMPACT_SHAPE_PROXYTYPE, other, &gimpact);
      dispatcher.registerClosestPointsCreateFunc(other, GIMPACT_SHAPE_PROXYTYPE, &gimpact);
    }
  }
};

}  // namespace

btCollisionWorld& collision_world() {
  static World w;
  return w.world;
}

}  // namespace cc::bullet_oracle
