// The input of mesh_mesh_distance and its fields; the kind's unit is
// src/harness/kinds/mesh_mesh_distance.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

/// Mesh a placed by pose_a and mesh b placed by pose_b, asked for the distance between their
/// surfaces; `library` names the hierarchies the library walks (mesh_collide.h, library_distance).
struct MeshMeshDistanceInput {
  MeshPair meshes;
  friend bool operator==(const MeshMeshDistanceInput&, const MeshMeshDistanceInput&) = default;
};

/// Its fields: the pair's (a, pose_a, b, pose_b, library) at the top of the case.
template <>
struct Fields<MeshMeshDistanceInput> {
  static constexpr auto list = std::tuple{field<&MeshMeshDistanceInput::meshes>("")};
};

}  // namespace cc::harness
