// The mesh_mesh_distance kind: the collision kinds' meshes and poses (two_meshes.cpp), walked by
// the library's distance traversal on Obb or sphere trees. The library's call, and what its cases
// are.
#include "harness/kinds/mesh_mesh_distance.h"

#include "harness/kinds/mesh_mesh.h"
#include "harness/model/mesh_collide.h"
#include "harness/kinds/separation_answer.h"

namespace cc::harness {
namespace {

using Collision = Query<MeshMeshInput>;

}  // namespace

Answer Query<MeshMeshDistanceInput>::ask(const MeshMeshDistanceInput& in) {
  return separation_answer(library_distance(in.meshes).separation);
}

MeshMeshDistanceInput Query<MeshMeshDistanceInput>::generate(ValueSource& v, const GenerateOptions& options) {
  MeshMeshDistanceInput in{Collision::generate(v, options).meshes};
  // The distance walks Obb and sphere trees: the drawn sphere trees stay, every other type is Obb.
  if (in.meshes.library.bv != BvType::sphere) in.meshes.library.bv = BvType::obb;
  return in;
}

void Query<MeshMeshDistanceInput>::touch(MeshMeshDistanceInput& in, ValueSource& v) {
  MeshMeshInput collision{in.meshes};
  Collision::touch(collision, v);
  in.meshes = collision.meshes;
}

Features Query<MeshMeshDistanceInput>::features(const MeshMeshDistanceInput& in) {
  return Collision::features(MeshMeshInput{in.meshes});
}

std::span<const std::string_view> Query<MeshMeshDistanceInput>::configurations() { return Collision::configurations(); }

void Query<MeshMeshDistanceInput>::recognise(const MeshMeshDistanceInput& in, Configurations& found) {
  Collision::recognise(MeshMeshInput{in.meshes}, found);
}

std::span<const BoundTerm> Query<MeshMeshDistanceInput>::bound_terms() { return {}; }

void Query<MeshMeshDistanceInput>::probe(const MeshMeshDistanceInput&, std::vector<bounds::Records>&) {}

}  // namespace cc::harness
