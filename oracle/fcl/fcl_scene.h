// FCL's two-level pipeline, for checking the library's: a broad-phase manager over
// CollisionObjects of BVHModel<OBBRSSd> meshes, then FCL's collide on each candidate pair with
// every contact asked for.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "collide/collision_world.h"

namespace cc::fcl_oracle {

class FclScene {
 public:
  /// The managers: Naive, SaP, SSaP, IntervalTree, DynamicAABBTree, DynamicAABBTree_Array,
  /// SpatialHashing (over the given world box, for the last).
  static std::vector<std::string> managers();
  /// Throws std::invalid_argument for an unknown manager.
  FclScene(const std::string& manager, const Aabb& world);
  ~FclScene();

  /// Objects are numbered in the order they are added, from 0.
  void add(const std::shared_ptr<const Mesh>& mesh, const RigidTransform& pose);
  void move(std::size_t object, const RigidTransform& pose);

  /// Updates the manager and collides every candidate; the colliding object pairs (smaller
  /// number first) with their triangle pairs, sorted. `candidates` gets the manager's count.
  std::vector<ObjectContact> collide(std::size_t& candidates);
  /// The objects' AABBs as FCL computed them for their current poses (what the manager sees).
  std::vector<Aabb> boxes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cc::fcl_oracle
