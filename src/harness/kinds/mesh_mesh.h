// mesh_mesh: every colliding pair of triangles of two placed meshes, build_bvh twice then collide.
#pragma once

#include "harness/kinds/two_meshes.h"

namespace cc::harness {

using MeshMeshInput = TwoMeshesInput<CollisionMode::all_pairs>;

}  // namespace cc::harness
