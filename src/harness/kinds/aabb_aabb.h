// aabb_aabb: two axis-aligned boxes, test_aabb_aabb.
#pragma once

#include "harness/kinds/query.h"

namespace cc::harness {

struct AabbAabbInput {
  Aabb a, b;
  friend bool operator==(const AabbAabbInput&, const AabbAabbInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<AabbAabbInput> {
  static constexpr auto list = std::tuple{field<&AabbAabbInput::a>("a"), field<&AabbAabbInput::b>("b")};
};

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
