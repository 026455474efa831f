// tri_tri_intersection: collision determination for two triangles, intersect_triangles: where
// they meet, as the corners of a point, a segment or a coplanar polygon.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/tri_tri_intersection.h"

namespace cc::harness {

template <>
struct Query<TriTriIntersectionInput> : QueryDefaults {
  static constexpr Band band = {0, BandSides::exact, 0,
                                "exact topology (orientation signs); each rounded corner within 2^-44 M kappa of the "
                                "exact one, M the largest coordinate, kappa its condition number (1 / sin of the "
                                "crossing angle, times L^2 / |n| of the plane's triangle)"};
  static constexpr Relations relations = {Relation::swap_shapes, Relation::permute_axes, Relation::flip_axis,
                                          Relation::scale, Relation::permute_vertices};
  static constexpr Judged judged = Judged::corners;

  static Answer ask(const TriTriIntersectionInput& in);
  static TriTriIntersectionInput generate(ValueSource& values, const GenerateOptions& options);
  /// As for test_triangle_triangle's kind: a vertex of b on a vertex of a, or on the middle of an
  /// edge of a.
  static void touch(TriTriIntersectionInput& in, ValueSource& values);
  /// As for test_triangle_triangle's kind: parallel edges or normals; a segment or point triangle.
  static Features features(const TriTriIntersectionInput& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const TriTriIntersectionInput& in, Configurations& found);
  static std::span<const BoundTerm> bound_terms();
  static void probe(const TriTriIntersectionInput& in, std::vector<bounds::Records>& records);
};

}  // namespace cc::harness
