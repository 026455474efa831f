// kdop_kdop: two point sets, each fitted with a k-DOP (fit_kdop<k>), then test_kdop_kdop.
#pragma once

#include <vector>

#include "harness/kinds/query.h"
#include "harness/model/inputs/kdop_kdop.h"

namespace cc::harness {

template <>
struct Query<KdopKdopInput> : QueryDefaults {
  static constexpr Band band = {0x1p-48, BandSides::conservative, 0,
                                "the overlap test is exact; fitting rounds 2- and 3-term projections outward by 4u of "
                                "their magnitude (k = 6 fits exactly)"};
  static constexpr Relations relations = {Relation::swap_shapes, Relation::permute_axes, Relation::flip_axis,
                                          Relation::scale, Relation::permute_points};

  static Answer ask(const KdopKdopInput& in);
  static KdopKdopInput generate(ValueSource& values, const GenerateOptions& options);
  /// B's points shifted along one axis so that the k-DOPs touch on one slab.
  static void touch(KdopKdopInput& in, ValueSource& values);
  /// Parallel: a point of each set on a common slab plane. Degenerate: a set of one point.
  static Features features(const KdopKdopInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const KdopKdopInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const KdopKdopInput& in, std::vector<bounds::Records>& records);
  /// A direction set not closed under the operation does not take it: 16 under permutations
  /// and flips, 24 under flips.
  static bool admits(const KdopKdopInput& in, Relation relation);
};

}  // namespace cc::harness
