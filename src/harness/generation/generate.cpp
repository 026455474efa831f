#include "harness/generation/generate.h"

#include "harness/generation/shapes.h"

namespace cc::harness {

Input generate(QueryKind kind, Choices& choices, const GenerateOptions& options) {
  // Huge magnitudes dwarf every other coordinate, and with them the library's band: one case in
  // seven gets them.
  const bool huge = choices.chance(15);
  ValueSource values(choices, ValueRange{8, true, huge, options.out_of_contract});
  switch (kind) {
    case QueryKind::ray_aabb: return detail::generate_ray_aabb(values, options);
    case QueryKind::sphere_sphere: return detail::generate_sphere_sphere(values, options);
    case QueryKind::aabb_aabb: return detail::generate_aabb_aabb(values, options);
    case QueryKind::kdop_kdop: return detail::generate_kdop_kdop(values, options);
    case QueryKind::obb_obb: return detail::generate_obb_obb(values, options);
    case QueryKind::tri_aabb: return detail::generate_tri_aabb(values, options);
    case QueryKind::tri_obb: return detail::generate_tri_obb(values, options);
    case QueryKind::tri_tri: return detail::generate_tri_tri(values, options);
    case QueryKind::mesh_mesh: return MeshMeshInput{detail::generate_meshes(values, options)};
    case QueryKind::mesh_mesh_first: return MeshMeshFirstInput{detail::generate_meshes(values, options)};
    case QueryKind::broadphase: return detail::generate_broadphase(values, options);
    case QueryKind::ray_mesh: return detail::generate_ray_mesh(values, options);
    case QueryKind::moving_obb: return detail::generate_moving_obb(values, options);
  }
  return {};
}

}  // namespace cc::harness
