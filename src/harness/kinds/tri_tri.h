// tri_tri: two triangles, test_triangle_triangle.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/tri_tri.h"

namespace cc::harness {

template <>
struct Query<TriTriInput> : QueryDefaults {
  static constexpr Band band = {0x1p-44, BandSides::conservative, 0,
                                "every axis is certified against 5u |axis|_1 of the coordinates, measured in the "
                                "conditioning of the axis (cross products of rounded edges)"};
  static constexpr Relations relations = {Relation::swap_shapes, Relation::permute_axes, Relation::flip_axis,
                                          Relation::scale, Relation::permute_vertices};

  static Answer ask(const TriTriInput& in);
  static TriTriInput generate(ValueSource& values, const GenerateOptions& options);
  /// A vertex of b on a vertex of a, or on the middle of an edge of a.
  static void touch(TriTriInput& in, ValueSource& values);
  /// Parallel: parallel edges or normals. Degenerate: a segment or point triangle.
  static Features features(const TriTriInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const TriTriInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const TriTriInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
