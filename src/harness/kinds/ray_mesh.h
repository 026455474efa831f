// ray_mesh: the first point where a ray meets a mesh, ray_mesh_closest through the case's
// hierarchy; also ray_mesh_any and ray_mesh_brute_force.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/ray_mesh.h"

namespace cc::harness {

template <>
struct Query<RayMeshInput> : QueryDefaults {
  static constexpr Band band = {0x1p-40, BandSides::conservative, 0,
                                "intersect_ray_triangle may hit a face the ray misses by 2^-44 R, R <= 2 M; the exact "
                                "margin is at most that distance. t is judged against ranges: no later than the exact "
                                "first point, no earlier than where the ray comes within that distance of a face's box"};
  static constexpr Relations relations = {Relation::permute_vertices, Relation::permute_faces};
  static constexpr Judged judged = Judged::first_pair;
  static constexpr bool builds_hierarchies = true;

  /// The closest hit: {t} and the pair (face, 0).
  static Answer ask(const RayMeshInput& in);
  /// "library.ray_mesh_any" (any hit: the face, without t) and "library.ray_mesh_brute_force".
  static const std::vector<Party<RayMeshInput>>& library_parties();
  static RayMeshInput generate(ValueSource& values, const GenerateOptions& options);
  /// Aimed at a vertex of a face, ending there.
  static void touch(RayMeshInput& in, ValueSource& values);
  /// Parallel: the ray along an axis or in the plane of a face. Degenerate: a zero direction or
  /// a degenerate face.
  static Features features(const RayMeshInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const RayMeshInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const RayMeshInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
