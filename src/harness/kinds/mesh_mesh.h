// mesh_mesh: every colliding pair of triangles of two placed meshes, build_bvh twice then
// collide; also the two-level pipeline, CollisionWorld.
#pragma once

#include "harness/kinds/two_meshes.h"
#include "harness/model/inputs/mesh_mesh.h"

namespace cc::harness {

template <>
struct Query<MeshMeshInput> : TwoMeshes<CollisionMode::all_pairs> {
  static constexpr Judged judged = Judged::all_pairs;

  /// "library.collision_world(refit)" and "library.collision_world(cube)": both meshes as
  /// objects of a CollisionWorld, boxed by fitted_box or bounding_cube, sweep-and-prune, then
  /// collide on the candidate.
  static const std::vector<Party<MeshMeshInput>>& library_parties();
  /// The object bounds of each placed mesh (its fitted box, radius and cube), which the
  /// pipeline's parties use.
  static std::span<const BoundTerm> bound_terms();
  static void probe(const MeshMeshInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
