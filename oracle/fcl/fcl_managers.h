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

/// Why collide() on `manager` would read memory outside its own lists, or "" when it would not.
/// FCL 0.7's SSaP reads objs_x at objs_y's last index (selectOptimalAxis): once unregisterObject
/// has missed the leaving object in objs_y (it searches lists sorted by where the boxes were
/// before they moved), objs_y is the longer and the read goes past objs_x's end, where what it
/// finds, and so whether it crashes, differs from process to process.
std::string fcl_manager_fault(const fcl::BroadPhaseCollisionManagerd& manager);

}  // namespace cc::fcl_oracle
