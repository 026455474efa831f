// The kinds of query the harness checks. Their names are used everywhere: on the command line,
// in case files and as folder names under corpora/.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace cc::harness {

enum class QueryKind { ray_aabb, sphere_sphere, aabb_aabb, kdop_kdop, obb_obb, tri_aabb, tri_obb, tri_tri };

inline constexpr std::array kAllQueryKinds = {QueryKind::ray_aabb, QueryKind::sphere_sphere, QueryKind::aabb_aabb,
                                              QueryKind::kdop_kdop, QueryKind::obb_obb,      QueryKind::tri_aabb,
                                              QueryKind::tri_obb,   QueryKind::tri_tri};

/// The query's name, e.g. "ray_aabb".
std::string_view name(QueryKind kind);

/// The query with that name, if any.
std::optional<QueryKind> query_kind_named(std::string_view name);

}  // namespace cc::harness
