// sphere_sphere: two spheres, test_sphere_sphere.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/sphere_sphere.h"

namespace cc::harness {

template <>
struct Query<SphereSphereInput> : QueryDefaults {
  static constexpr Band band = {0x1p-46, BandSides::conservative, 0,
                                "|d|^2 - (r_a+r_b)^2 is certified against an 8u bound: at most 88u of the scale between "
                                "surfaces"};
  static constexpr Relations relations = {Relation::swap_shapes, Relation::permute_axes, Relation::flip_axis,
                                          Relation::scale};
  /// Spheres have no parallel configuration.
  static constexpr bool parallel_applies = false;

  static Answer ask(const SphereSphereInput& in);
  static SphereSphereInput generate(ValueSource& values, const GenerateOptions& options);
  /// B's centre at the radii's sum from A's along a coordinate axis.
  static void touch(SphereSphereInput& in, ValueSource& values);
  /// Degenerate: a radius 0.
  static Features features(const SphereSphereInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const SphereSphereInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const SphereSphereInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
