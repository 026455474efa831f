// tri_tri_distance: the distance between two triangles and a closest pair of points,
// distance_triangle_triangle, each answer with the error bounds it certifies.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/tri_tri_distance.h"

namespace cc::harness {

template <>
struct Query<TriTriDistanceInput> : QueryDefaults {
  static constexpr Band band = {0, BandSides::exact, 0,
                                "the distance and each witness within the error bounds the answer certifies "
                                "(collide/separation.h); the points as far apart as the distance says"};
  static constexpr Relations relations = {Relation::swap_shapes, Relation::permute_axes, Relation::flip_axis,
                                          Relation::scale, Relation::permute_vertices};
  static constexpr Judged judged = Judged::distance;

  /// Hit when the distance is 0; params: the distance, on_a, on_b, distance_error, point_error.
  static Answer ask(const TriTriDistanceInput& in);
  static TriTriDistanceInput generate(ValueSource& values, const GenerateOptions& options);
  /// As for test_triangle_triangle's kind: a vertex of b on a vertex of a, or on the middle of an
  /// edge of a (distance 0).
  static void touch(TriTriDistanceInput& in, ValueSource& values);
  /// As for test_triangle_triangle's kind: parallel edges or normals; a segment or point triangle.
  static Features features(const TriTriDistanceInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const TriTriDistanceInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const TriTriDistanceInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
