// sphere_sphere_distance: the signed distance between two balls and a pair of points realising it,
// distance_sphere_sphere, each answer with the error bounds it certifies.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/sphere_sphere_distance.h"

namespace cc::harness {

template <>
struct Query<SphereSphereDistanceInput> : QueryDefaults {
  static constexpr Band band = {0, BandSides::exact, 0,
                                "the signed distance and each witness within the error bounds the answer certifies "
                                "(collide/separation.h); the points as far apart as the distance says"};
  static constexpr Relations relations = {Relation::swap_shapes, Relation::permute_axes, Relation::flip_axis,
                                          Relation::scale};
  static constexpr Judged judged = Judged::distance;
  /// Balls have no parallel configuration.
  static constexpr bool parallel_applies = false;

  /// Hit when the signed distance is <= 0; params: the distance, on_a, on_b, distance_error,
  /// point_error.
  static Answer ask(const SphereSphereDistanceInput& in);
  static SphereSphereDistanceInput generate(ValueSource& values, const GenerateOptions& options);
  /// As for test_sphere_sphere's kind: b's centre at the radii's sum from a's along an axis.
  static void touch(SphereSphereDistanceInput& in, ValueSource& values);
  /// Degenerate: a radius 0.
  static Features features(const SphereSphereDistanceInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const SphereSphereDistanceInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const SphereSphereDistanceInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
