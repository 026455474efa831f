// sphere_obb_distance: the signed distance between a ball and an oriented box and a pair of points
// realising it (the penetration depth where they overlap), distance_sphere_obb, each answer with
// the error bounds it certifies.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/sphere_obb_distance.h"

namespace cc::harness {

template <>
struct Query<SphereObbDistanceInput> : QueryDefaults {
  static constexpr Band band = {0, BandSides::exact, 0,
                                "the signed distance and each witness within the error bounds the answer certifies "
                                "(collide/separation.h); the points as far apart as the distance says"};
  static constexpr Relations relations = {Relation::permute_axes, Relation::flip_axis, Relation::scale};
  static constexpr Judged judged = Judged::distance;
  /// A ball has no parallel configuration with a box.
  static constexpr bool parallel_applies = false;

  /// Hit when the signed distance is <= 0; params: the distance, on_a (the ball's), on_b (the
  /// box's), distance_error, point_error.
  static Answer ask(const SphereObbDistanceInput& in);
  static SphereObbDistanceInput generate(ValueSource& values, const GenerateOptions& options);
  /// The ball's centre moved to the radius from the middle of a face of the box, outside it.
  static void touch(SphereObbDistanceInput& in, ValueSource& values);
  /// Degenerate: a radius 0 or a half extent 0.
  static Features features(const SphereObbDistanceInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const SphereObbDistanceInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const SphereObbDistanceInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
