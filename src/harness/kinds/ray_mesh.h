// ray_mesh: the first point where a ray meets a mesh, through the library's hierarchy.
#pragma once

#include "harness/formats/parts.h"

namespace cc::harness {

/// The first point where a ray meets a mesh (its own frame), through the library's hierarchy.
struct RayMeshInput {
  MeshRef mesh;
  Ray ray;
  LibraryBvh library;
  friend bool operator==(const RayMeshInput&, const RayMeshInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<RayMeshInput> {
  static constexpr auto list = std::tuple{field<&RayMeshInput::ray>(""), field<&RayMeshInput::mesh>("mesh"),
                                          field<&RayMeshInput::library>("library")};
};

}  // namespace cc::harness
