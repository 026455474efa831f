// tri_aabb: a triangle against an axis-aligned box, test_triangle_aabb.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/tri_aabb.h"

namespace cc::harness {

template <>
struct Query<TriAabbInput> : QueryDefaults {
  static constexpr Band band = {0x1p-44, BandSides::conservative, 0,
                                "box axes are exact; other axes are certified against 5u |axis|_1 of the coordinates, "
                                "measured in the conditioning of the axis"};
  static constexpr Relations relations = {Relation::permute_axes, Relation::flip_axis, Relation::scale,
                                          Relation::permute_vertices};

  static Answer ask(const TriAabbInput& in);
  static TriAabbInput generate(ValueSource& values, const GenerateOptions& options);
  /// A vertex of the triangle on a point of the box's boundary.
  static void touch(TriAabbInput& in, ValueSource& values);
  /// Parallel: an edge or the normal along a coordinate axis. Degenerate: a segment or point
  /// triangle, a flat box.
  static Features features(const TriAabbInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const TriAabbInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const TriAabbInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
