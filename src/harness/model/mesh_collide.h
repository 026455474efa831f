// The library's side of a mesh query: hierarchies built once per mesh and walked per case.
#pragma once

#include <memory>

#include "collide/bvh_collide.h"
#include "collide/bvh_distance.h"
#include "collide/ray_mesh.h"
#include "harness/model/mesh_query.h"

namespace cc::harness {

/// The hierarchy of a mesh for the given volume type and build options, built on first use and
/// kept while the mesh lives (campaign cases reuse FCL's test meshes thousands of times).
template <class BV>
std::shared_ptr<const Bvh<BV>> cached_bvh(const std::shared_ptr<const Mesh>& mesh, const BuildOptions& options);

/// The options to build a case's hierarchies with: the case's, with hull points when its update
/// is the exact one (BuildOptions::hull_points).
BuildOptions build_options(const LibraryBvh& library);

/// The library's answer to a mesh query, with its counters: both meshes' hierarchies of the
/// case's type and build, walked with its update and descent options (lazy_top_down: two lazy
/// trees made anew, so the counters are those of a first query).
CollisionResult library_collide(const MeshPair& meshes, CollisionMode mode);
/// The library's distance between two placed meshes (bvh_distance.h) through both meshes'
/// hierarchies of the case's build: sphere trees for a case of sphere trees, Obb trees for every
/// other volume type (the distance walks those two); the update and descent do not apply, and a
/// lazy build is walked whole.
MeshSeparation library_distance(const MeshPair& meshes);
/// The library's answer to a ray against a mesh through the mesh's hierarchy of the given type and
/// build: the closest hit, or (any_hit) the first one found (lazy_top_down: through the whole
/// top-down tree, which the rays take eager).
RayMeshHit library_ray_mesh(const std::shared_ptr<const Mesh>& mesh, const LibraryBvh& library, const Ray& ray,
                            bool any_hit);

}  // namespace cc::harness
