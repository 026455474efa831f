// tri_obb_distance: the signed distance between a triangle and an oriented box and a pair of
// points realising it (the penetration depth where they overlap), distance_triangle_obb, each
// answer with the error bounds it certifies.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/tri_obb_distance.h"

namespace cc::harness {

template <>
struct Query<TriObbDistanceInput> : QueryDefaults {
  static constexpr Band band = {0, BandSides::exact, 0,
                                "the signed distance and each witness within the error bounds the answer certifies "
                                "(collide/triangle_box_distance.h); the points as far apart as the distance says"};
  static constexpr Relations relations = {Relation::permute_axes, Relation::flip_axis, Relation::scale,
                                          Relation::permute_vertices};
  static constexpr Judged judged = Judged::distance;

  /// Hit when the signed distance is <= 0; params: the distance, on_a (on the triangle), on_b (on
  /// the box), distance_error, point_error.
  static Answer ask(const TriObbDistanceInput& in);
  /// The collision kind's triangles and boxes: touching at a vertex, in a face's plane, through
  /// point and segment boxes, slivers slid to a margin of the decision in the regimes of its bound
  /// (gaps and depths from a few ulps to half the size either way, edges and planes parallel to
  /// the box's faces: closest points not unique).
  static TriObbDistanceInput generate(ValueSource& values, const GenerateOptions& options);
  /// A vertex of the triangle on a point of the box's boundary.
  static void touch(TriObbDistanceInput& in, ValueSource& values);
  /// As for the collision kind: an edge or the normal along an axis of the box, a degenerate
  /// triangle, a zero half extent.
  static Features features(const TriObbDistanceInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const TriObbDistanceInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const TriObbDistanceInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
