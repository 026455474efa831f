// A Bullet collision world for the parties that go through btCollisionWorld::contactPairTest
// (internal to oracle/bullet).
#pragma once

#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>

namespace cc::bullet_oracle {

/// One world per process: the default collision configuration's algorithms, and GImpact's,
/// registered for contact points and for closest points (which contactPairTest asks: without it
/// a pair of GImpact shapes gets an empty algorithm and no contact). Objects are not added to
/// it; contactPairTest pairs them directly.
btCollisionWorld& collision_world();

}  // namespace cc::bullet_oracle
