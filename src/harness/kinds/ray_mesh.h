// ray_mesh: the first point where a ray meets a mesh, through the library's hierarchy.
#pragma once

#include "collide/ray_aabb.h"
#include "harness/model/mesh_query.h"

namespace cc::harness {

/// The first point where a ray meets a mesh (its own frame), through the library's hierarchy.
struct RayMeshInput {
  MeshRef mesh;
  Ray ray;
  LibraryBvh library;
  friend bool operator==(const RayMeshInput&, const RayMeshInput&) = default;
};

}  // namespace cc::harness
