// The input of mesh_mesh_first and its fields; the kind's unit is src/harness/kinds/mesh_mesh_first.h.
#pragma once

#include "harness/model/inputs/two_meshes.h"

namespace cc::harness {

using MeshMeshFirstInput = TwoMeshesInput<CollisionMode::first_hit>;

}  // namespace cc::harness
