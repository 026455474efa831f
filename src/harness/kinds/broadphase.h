// broadphase: the overlapping pairs of a set of boxes, frame by frame (ColumnSweep); also
// SweepAndPrune and sort_and_sweep.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/broadphase.h"

namespace cc::harness {

template <>
struct Query<BroadphaseInput> : QueryDefaults {
  static constexpr Band band = {0, BandSides::exact, 0, "comparisons of the given bounds only (closed boxes): exact"};
  static constexpr Relations relations = {Relation::permute_axes, Relation::flip_axis, Relation::scale,
                                          Relation::permute_objects};
  static constexpr Judged judged = Judged::frames;

  /// ColumnSweep with the boxes added, moved and removed as the slots say: every frame's pairs
  /// (as slots), sorted; a box outside the domain makes the answer no hit.
  static Answer ask(const BroadphaseInput& in);
  /// "library.sweep_and_prune" (SweepAndPrune the same way) and "library.sort_and_sweep" (a full
  /// sort every frame).
  static const std::vector<Party<BroadphaseInput>>& library_parties();
  static BroadphaseInput generate(ValueSource& values, const GenerateOptions& options);
  /// Two boxes of a frame: the second put face to face against the first on one axis.
  static void touch(BroadphaseInput& in, ValueSource& values);
  /// Parallel: two boxes share a bound value on an axis (equal endpoints). Degenerate: a flat or
  /// point box, or two identical boxes.
  static Features features(const BroadphaseInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const BroadphaseInput& in, Configurations& found);
  /// No certified bound: the sweeps compare the given bounds.
  static std::span<const BoundTerm> bound_terms();
  static void probe(const BroadphaseInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
