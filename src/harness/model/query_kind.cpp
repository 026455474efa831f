#include "harness/model/query_kind.h"

namespace cc::harness {

std::string_view name(QueryKind kind) {
  switch (kind) {
    case QueryKind::ray_aabb: return "ray_aabb";
    case QueryKind::sphere_sphere: return "sphere_sphere";
    case QueryKind::aabb_aabb: return "aabb_aabb";
    case QueryKind::kdop_kdop: return "kdop_kdop";
    case QueryKind::obb_obb: return "obb_obb";
    case QueryKind::tri_aabb: return "tri_aabb";
    case QueryKind::tri_obb: return "tri_obb";
    case QueryKind::tri_tri: return "tri_tri";
    case QueryKind::mesh_mesh: return "mesh_mesh";
    case QueryKind::mesh_mesh_first: return "mesh_mesh_first";
    case QueryKind::broadphase: return "broadphase";
    case QueryKind::ray_mesh: return "ray_mesh";
    case QueryKind::moving_obb: return "moving_obb";
  }
  return "?";
}

std::optional<QueryKind> query_kind_named(std::string_view text) {
  for (QueryKind kind : kAllQueryKinds) {
    if (name(kind) == text) return kind;
  }
  return std::nullopt;
}

}  // namespace cc::harness
