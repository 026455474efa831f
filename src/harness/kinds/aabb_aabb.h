// aabb_aabb: two axis-aligned boxes, test_aabb_aabb.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/aabb_aabb.h"

namespace cc::harness {

template <>
struct Query<AabbAabbInput> : QueryDefaults {
  static constexpr Band band = {0, BandSides::exact, 0, "comparisons of inputs only: exact"};
  static constexpr Relations relations = {Relation::swap_shapes, Relation::permute_axes, Relation::flip_axis,
                                          Relation::scale};

  static Answer ask(const AabbAabbInput& in);
  static AabbAabbInput generate(ValueSource& values, const GenerateOptions& options);
  /// B against a face of A on one axis.
  static void touch(AabbAabbInput& in, ValueSource& values);
  /// Parallel: equal face coordinates. Degenerate: a zero extent.
  static Features features(const AabbAabbInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const AabbAabbInput& in, Configurations& found);
  /// No certified bound: the test compares its inputs.
  static std::span<const BoundTerm> bound_terms();
  static void probe(const AabbAabbInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
