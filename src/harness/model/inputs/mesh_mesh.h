// The input of mesh_mesh and its fields; the kind's unit is src/harness/kinds/mesh_mesh.h.
#pragma once

#include "harness/model/inputs/two_meshes.h"

namespace cc::harness {

using MeshMeshInput = TwoMeshesInput<CollisionMode::all_pairs>;

}  // namespace cc::harness
