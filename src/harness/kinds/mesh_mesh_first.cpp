// The mesh_mesh_first kind's own pieces (the rest are both mesh kinds', two_meshes.cpp).
#include "harness/kinds/mesh_mesh_first.h"

namespace cc::harness {

std::span<const BoundTerm> Query<MeshMeshFirstInput>::bound_terms() { return {}; }

void Query<MeshMeshFirstInput>::probe(const MeshMeshFirstInput&, std::vector<bounds::Records>&) {}

}  // namespace cc::harness
