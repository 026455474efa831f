// mesh_mesh_first: whether two placed meshes collide, and one colliding pair if they do.
#pragma once

#include "harness/kinds/two_meshes.h"
#include "harness/model/inputs/mesh_mesh_first.h"

namespace cc::harness {

template <>
struct Query<MeshMeshFirstInput> : TwoMeshes<CollisionMode::first_hit> {
  static constexpr Judged judged = Judged::first_pair;

  /// No certified bound of its own (collide's tests are the primitive kinds').
  static std::span<const BoundTerm> bound_terms();
  static void probe(const MeshMeshFirstInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
