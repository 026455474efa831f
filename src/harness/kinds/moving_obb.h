// moving_obb: two boxes moving with constant velocities over a step, sweep_obb_obb; also
// sweep_aabb_aabb for axis-aligned boxes.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/moving_obb.h"

namespace cc::harness {

template <>
struct Query<MovingObbInput> : QueryDefaults {
  static constexpr Band band = {0x1p-40, BandSides::conservative, 0,
                                "at the reported times no axis (as given, not normalised) separates the boxes by more "
                                "than 2^-40 M; t_first and t_last are judged against the exact window and that of the "
                                "boxes grown by the band"};
  static constexpr Relations relations = {Relation::swap_shapes, Relation::permute_axes, Relation::flip_axis,
                                          Relation::scale};

  /// Hit and {t_first, t_last}.
  static Answer ask(const MovingObbInput& in);
  /// "library.sweep_aabb_aabb": applicable when both boxes are axis-aligned and their bounds,
  /// centre -+ half, are exact.
  static const std::vector<Party<MovingObbInput>>& library_parties();
  /// Two boxes as the static pair's generator draws them, given velocities and moved back so
  /// that they meet at a chosen time of the step (or never); pairs in the regimes of
  /// sweep_obb_obb's bound slid to an exact margin.
  static MovingObbInput generate(ValueSource& values, const GenerateOptions& options);
  /// Face to face at rest, then moved back so that they meet at t = 1/2.
  static void touch(MovingObbInput& in, ValueSource& values);
  /// Parallel: parallel box axes, or a rate of exactly 0 along an axis. Degenerate: a zero half
  /// extent, or no relative motion.
  static Features features(const MovingObbInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const MovingObbInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const MovingObbInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
