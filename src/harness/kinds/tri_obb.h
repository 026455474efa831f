// tri_obb: a triangle against an oriented box, test_triangle_obb.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/tri_obb.h"

namespace cc::harness {

template <>
struct Query<TriObbInput> : QueryDefaults {
  static constexpr Band band = {0x1p-40, BandSides::conservative, 0,
                                "the box's axes are exact in its frame, the others certified against 5u |axis|_1 of the "
                                "coordinates; plus the rounding of the change into the box's frame and eta of the extents"};
  static constexpr Relations relations = {Relation::permute_axes, Relation::flip_axis, Relation::scale,
                                          Relation::permute_vertices};

  static Answer ask(const TriObbInput& in);
  static TriObbInput generate(ValueSource& values, const GenerateOptions& options);
  /// A vertex of the triangle on a point of the box's boundary (placed by the box's frame).
  static void touch(TriObbInput& in, ValueSource& values);
  /// Parallel: an edge or the normal along an axis of the box. Degenerate: a segment or point
  /// triangle, a zero half extent.
  static Features features(const TriObbInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const TriObbInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const TriObbInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
