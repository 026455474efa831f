// ray_aabb: a ray (or segment) against an axis-aligned box, intersect_ray_aabb; also the batched
// test_ray_aabbs.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/ray_aabb.h"

namespace cc::harness {

template <>
struct Query<RayAabbInput> : QueryDefaults {
  static constexpr Band band = {0x1p-46, BandSides::conservative, 0x1p-50,
                                "slab parameters carry 3 roundings and are padded outward by 8u; a miss shorter than 44u of "
                                "the scale can read as a hit. Parallel slabs are decided exactly. t within 4u, plus u to "
                                "round the exact t"};
  static constexpr Relations relations = {Relation::permute_axes, Relation::flip_axis, Relation::scale};

  /// Hit and {t_enter, t_exit}.
  static Answer ask(const RayAabbInput& in);
  /// "library.test_ray_aabbs": the batched test, every kernel this processor runs, the case's
  /// box at place 3 of 11 (in a vector block) and at place 10 (in the scalar tail), the others
  /// boxes made from it; a kernel or a place differing from intersect_ray_aabb fails.
  static const std::vector<Party<RayAabbInput>>& library_parties();
  static RayAabbInput generate(ValueSource& values, const GenerateOptions& options);
  /// Aimed at a point of the box's boundary; sometimes a segment ending there.
  static void touch(RayAabbInput& in, ValueSource& values);
  /// Parallel: a direction component 0 (or parallel by contract). Degenerate: a zero direction,
  /// tmin = tmax, a flat box.
  static Features features(const RayAabbInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const RayAabbInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const RayAabbInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
