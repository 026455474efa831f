// obb_obb: two oriented boxes, test_obb_obb.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/obb_obb.h"

namespace cc::harness {

template <>
struct Query<ObbObbInput> : QueryDefaults {
  static constexpr Band band = {0x1p-40, BandSides::conservative, 0,
                                "each axis is certified against 32u of the inputs plus 6 eta (eta = 2^-48, the "
                                "orthonormality tolerance) of the extents; the exact reference's parallelepiped differs "
                                "from the library's box by eta"};
  static constexpr Relations relations = {Relation::swap_shapes, Relation::permute_axes, Relation::flip_axis,
                                          Relation::scale};

  static Answer ask(const ObbObbInput& in);
  static ObbObbInput generate(ValueSource& values, const GenerateOptions& options);
  /// B against a face of A.
  static void touch(ObbObbInput& in, ValueSource& values);
  /// Parallel: parallel axes. Degenerate: a zero half extent.
  static Features features(const ObbObbInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const ObbObbInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const ObbObbInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
