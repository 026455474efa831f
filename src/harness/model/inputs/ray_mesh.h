// The input of ray_mesh and its fields; the kind's unit is src/harness/kinds/ray_mesh.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

/// The first point where a ray meets a mesh (its own frame), through the library's hierarchy.
struct RayMeshInput {
  MeshRef mesh;
  Ray ray;
  LibraryBvh library;
  friend bool operator==(const RayMeshInput&, const RayMeshInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record: origin, dir, tmin, tmax,
/// mesh, library.
template <>
struct Fields<RayMeshInput> {
  static constexpr auto list = std::tuple{field<&RayMeshInput::ray>(""), field<&RayMeshInput::mesh>("mesh"),
                                          field<&RayMeshInput::library>("library")};
};

}  // namespace cc::harness
