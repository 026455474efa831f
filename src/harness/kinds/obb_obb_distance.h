// obb_obb_distance: the signed distance between two oriented boxes and a pair of points realising
// it (the penetration depth where they overlap), distance_obb_obb, each answer with the error
// bounds it certifies.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/obb_obb_distance.h"

namespace cc::harness {

template <>
struct Query<ObbObbDistanceInput> : QueryDefaults {
  static constexpr Band band = {0, BandSides::exact, 0,
                                "the signed distance and each witness within the error bounds the answer certifies "
                                "(collide/obb_distance.h); the points as far apart as the distance says"};
  static constexpr Relations relations = {Relation::swap_shapes, Relation::permute_axes, Relation::flip_axis,
                                          Relation::scale};
  static constexpr Judged judged = Judged::distance;

  /// Hit when the signed distance is <= 0; params: the distance, on_a, on_b, distance_error,
  /// point_error.
  static Answer ask(const ObbObbDistanceInput& in);
  /// The collision kind's pairs of boxes (against a face, nearly parallel edges, common centres,
  /// at a margin of the decision in the regimes of its bound), and b against a face of a at a
  /// drawn signed gap: 0, a few ulps and 2^-1 to 2^-60 of the size either way (just apart, just
  /// overlapping, shallow and deep), its axes a's (parallel faces and edges) or any.
  static ObbObbDistanceInput generate(ValueSource& values, const GenerateOptions& options);
  /// B against a face of A.
  static void touch(ObbObbDistanceInput& in, ValueSource& values);
  /// As for two boxes' collision: parallel axes, a zero half extent.
  static Features features(const ObbObbDistanceInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const ObbObbDistanceInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const ObbObbDistanceInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
