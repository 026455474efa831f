// mesh_mesh_first: whether two placed meshes collide, and one colliding pair if they do.
#pragma once

#include "harness/kinds/two_meshes.h"

namespace cc::harness {

using MeshMeshFirstInput = TwoMeshesInput<CollisionMode::first_hit>;

}  // namespace cc::harness
