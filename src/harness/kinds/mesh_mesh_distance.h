// mesh_mesh_distance: the distance between the surfaces of two placed meshes and a closest pair
// of points, distance() through both meshes' hierarchies, with the error bounds it certifies.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/mesh_mesh_distance.h"

namespace cc::harness {

template <>
struct Query<MeshMeshDistanceInput> : QueryDefaults {
  static constexpr Band band = {0, BandSides::exact, 0,
                                "the distance and each witness within the error bounds the answer certifies "
                                "(collide/bvh_distance.h); the points as far apart as the distance says"};
  /// As for the collision kinds on two meshes (kinds/two_meshes.h): the world's axes permuted;
  /// the faces, or each face's vertices, reordered.
  static constexpr Relations relations = {Relation::permute_axes, Relation::permute_vertices, Relation::permute_faces};
  static constexpr Judged judged = Judged::distance;
  static constexpr bool builds_hierarchies = true;

  /// Hit when the distance is 0 (the surfaces touch or cross); params: the distance, on_a,
  /// on_b, distance_error, point_error (mesh_collide.h, library_distance).
  static Answer ask(const MeshMeshDistanceInput& in);
  /// The collision kinds' cases (FCL's test meshes at FCL's test poses and brought to near
  /// contact, exact poses touching at a vertex, procedural meshes with degenerate faces, poses
  /// at the orthonormality tolerance far from the origin), with Obb or sphere trees.
  static MeshMeshDistanceInput generate(ValueSource& values, const GenerateOptions& options);
  /// b translated so that one of its vertices meets one of a's.
  static void touch(MeshMeshDistanceInput& in, ValueSource& values);
  /// As for the collision kinds: parallel frames, degenerate faces.
  static Features features(const MeshMeshDistanceInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const MeshMeshDistanceInput& in, Configurations& found);
  /// No bound of its own: the answer is certified after the fact from the triangle distances'
  /// bounds and the placement's.
  static std::span<const BoundTerm> bound_terms();
  static void probe(const MeshMeshDistanceInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
