// The two-level pipeline for many moving objects: sweep-and-prune in columns over the objects'
// boxes prunes the pairs that cannot touch; the hierarchies of the pairs left are tested
// against each other (BVH-vs-BVH) for their colliding triangle pairs.
#pragma once

#include <memory>
#include <vector>

#include "collide/bvh_collide.h"
#include "collide/object_bounds.h"
#include "collide/column_sweep.h"

namespace cc {

/// How a rotating object is bounded each frame at the first level.
enum class RotationBounds {
  bounding_cube,    // the cube that holds the object in every rotation: only moved each frame
  refit,            // the box fitted around the placed vertices: tighter, a pass over them
  bounding_sphere,  // the ball around the object (mesh_ball), moved each frame (placed_ball): the
                    // cube around it for the sweep, then the balls' own test on its candidates
};

/// Two objects that collide, and their colliding triangle pairs (faces of the first object's
/// mesh, faces of the second's), sorted.
struct ObjectContact {
  ObjectPair objects;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> triangles;
};

/// Objects (a mesh with its hierarchy, and a pose) in one world. Per frame: move(), then
/// broad_phase() (boxes, then ColumnSweep), then narrow_phase() on its candidates.
///  - The candidates are the pairs whose boxes overlap (with bounding_sphere, and whose balls
///    do, by test_sphere_sphere); boxes and balls hold the placed meshes (see object_bounds.h),
///    so no colliding pair is pruned. The contacts are collide()'s on every
///    candidate (its contract: closed sets, conservative leaf tests, surfaces only).
///  - Ids come from add() and are not reused; a removed object leaves at once.
template <class BV>
class CollisionWorld {
 public:
  explicit CollisionWorld(RotationBounds bounds = RotationBounds::refit, CollideOptions options = {})
      : bounds_(bounds), options_(options) {}

  ObjectId add(std::shared_ptr<const Mesh> mesh, std::shared_ptr<const Bvh<BV>> bvh, const RigidTransform& pose);
  void remove(ObjectId id);
  void move(ObjectId id, const RigidTransform& pose) { objects_.at(id).pose = pose; }

  /// Refits or moves every object's box and updates the broadphase; returns the candidates.
  const std::vector<ObjectPair>& broad_phase();
  /// collide() on every candidate of the last broad_phase(); the pairs that collide.
  std::vector<ObjectContact> narrow_phase() const;

  const ColumnSweep& sweep() const { return sap_; }
  Aabb box_of(ObjectId id) const;

 private:
  struct Object {
    std::shared_ptr<const Mesh> mesh;
    std::shared_ptr<const Bvh<BV>> bvh;
    RigidTransform pose;
    double radius = 0;  // rotation_radius, for bounding_cube
    Sphere ball;        // mesh_ball, for bounding_sphere
    bool alive = true;
  };
  RotationBounds bounds_;
  CollideOptions options_;
  std::vector<Object> objects_;
  ColumnSweep sap_;
  std::vector<ObjectPair> candidates_;
};

}  // namespace cc
