// FCL's seven broad-phase managers by name (internal to oracle/fcl): what the scene's pipeline
// and the second opinions on boxes over frames build.
#pragma once

#include <fcl/broadphase/broadphase_collision_manager.h>

#include <memory>
#include <string>
#include <vector>

#include "collide/aabb.h"

namespace cc::fcl_oracle {

/// Naive, SaP, SSaP, IntervalTree, DynamicAABBTree, DynamicAABBTree_Array, SpatialHashing.
const std::vector<std::string>& fcl_manager_names();

/// A new manager. SpatialHashing hashes the `world` box with cells of the given size (objects
/// outside it are kept aside by FCL). Throws std::invalid_argument for an unknown name.
std::unique_ptr<fcl::BroadPhaseCollisionManagerd> make_fcl_manager(const std::string& name, const Aabb& world,
                                                                   double cell);

}  // namespace cc::fcl_oracle
