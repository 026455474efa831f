// The kinds of query the harness checks. Their names are used everywhere: on the command line,
// in case files and as folder names under corpora/.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace cc::harness {

enum class QueryKind {
  ray_aabb,
  sphere_sphere,
  aabb_aabb,
  kdop_kdop,
  obb_obb,
  tri_aabb,
  tri_obb,
  tri_tri,
  mesh_mesh,        // all colliding triangle pairs of two meshes
  mesh_mesh_first,  // the first colliding pair found, if any
  broadphase,       // the overlapping pairs of a set of boxes, frame by frame
  ray_mesh,         // the first point where a ray meets a mesh
  moving_obb,       // whether and when two boxes moving over a step first meet
};

inline constexpr std::array kAllQueryKinds = {
    QueryKind::ray_aabb, QueryKind::sphere_sphere, QueryKind::aabb_aabb, QueryKind::kdop_kdop, QueryKind::obb_obb,
    QueryKind::tri_aabb, QueryKind::tri_obb,       QueryKind::tri_tri,   QueryKind::mesh_mesh, QueryKind::mesh_mesh_first,
    QueryKind::broadphase, QueryKind::ray_mesh,    QueryKind::moving_obb};

/// True for the queries on two meshes (an answer is a set of triangle pairs).
constexpr bool is_mesh_query(QueryKind kind) { return kind == QueryKind::mesh_mesh || kind == QueryKind::mesh_mesh_first; }

/// The query's name, e.g. "ray_aabb".
std::string_view name(QueryKind kind);

/// The query with that name, if any.
std::optional<QueryKind> query_kind_named(std::string_view name);

}  // namespace cc::harness
