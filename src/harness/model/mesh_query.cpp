#include "harness/model/mesh_query.h"

namespace cc::harness {

bool operator==(const MeshRef& a, const MeshRef& b) {
  if (a.source != b.source || a.file != b.file || a.recipe != b.recipe) return false;
  if (a.mesh == b.mesh) return true;
  return a.mesh && b.mesh && *a.mesh == *b.mesh;
}

MeshRef triangles_mesh(Mesh mesh) {
  MeshRef r;
  r.source = MeshRef::Source::triangles;
  r.mesh = std::make_shared<const Mesh>(std::move(mesh));
  return r;
}

MeshRef procedural_mesh(const ProceduralMesh& recipe) {
  MeshRef r;
  r.source = MeshRef::Source::procedural;
  r.recipe = recipe;
  r.mesh = std::make_shared<const Mesh>(make_mesh(recipe));
  return r;
}

std::string_view to_string(BvType t) {
  switch (t) {
    case BvType::aabb: return "aabb";
    case BvType::obb: return "obb";
    case BvType::kdop6: return "kdop6";
    case BvType::kdop14: return "kdop14";
    case BvType::kdop16: return "kdop16";
    case BvType::kdop18: return "kdop18";
    case BvType::kdop24: return "kdop24";
    case BvType::kdop26: return "kdop26";
    case BvType::sphere: return "sphere";
  }
  return "?";
}

std::optional<BvType> bv_type_named(std::string_view name) {
  for (BvType t : kAllBvTypes) {
    if (to_string(t) == name) return t;
  }
  return std::nullopt;
}

}  // namespace cc::harness
