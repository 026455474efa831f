// FCL's mesh hierarchies for the hierarchy benchmarks: BVHModel built from a library Mesh, and
// what it occupies. (Queries go through oracle/fcl's fcl_collide_meshes, which keeps its own
// models.) FCL stays inside fcl_models.cpp.
#pragma once

#include <cstddef>
#include <string_view>

#include "collide/mesh.h"

namespace cc::bench {

/// FCL's volume types with a library counterpart (kIOS: up to five spheres and an OBB per node,
/// FCL's nearest to the library's sphere trees, which it has no plain form of).
enum class FclBv { aabb, obb, kdop16, kdop18, kdop24, kios };
std::string_view to_string(FclBv bv);

/// Builds fcl::BVHModel<BV> of the mesh with FCL's default splitter (mean), and returns the
/// bytes it holds: vertices, triangles, nodes (fcl::BVNode<BV>) and primitive indices, the
/// arrays endModel() leaves sized to the mesh. The model is destroyed before returning.
std::size_t build_fcl_model(FclBv bv, const Mesh& mesh);

}  // namespace cc::bench
