// The metamorphic relations (metamorphic.h), and the set of them a kind takes (its unit says).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace cc::harness {

enum class Relation {
  swap_shapes,       // the fields a and b exchanged (two shapes of one type)
  permute_axes,      // x, y, z permuted (parameter: which of the 6 permutations)
  flip_axis,         // one coordinate negated, a mirror image (parameter: the axis)
  scale,             // every length multiplied by 2^parameter (ray: origin, direction and box)
  permute_vertices,  // each triangle's vertices reordered (a triangle, every face of a mesh)
  permute_faces,     // a mesh's faces reordered: the answer's faces renamed
  permute_points,    // each point set reordered
  permute_objects,   // the slots of boxes over frames reordered, in every frame: the pairs renamed
};

/// Every relation, in the order above.
inline constexpr Relation kAllRelations[] = {Relation::swap_shapes,      Relation::permute_axes,
                                             Relation::flip_axis,        Relation::scale,
                                             Relation::permute_vertices, Relation::permute_faces,
                                             Relation::permute_points,   Relation::permute_objects};

std::string_view to_string(Relation r);

/// A set of relations.
class Relations {
 public:
  constexpr Relations(std::initializer_list<Relation> relations) {
    for (Relation r : relations) bits_ |= bit(r);
  }
  constexpr bool has(Relation r) const { return (bits_ & bit(r)) != 0; }

 private:
  static constexpr std::uint32_t bit(Relation r) { return std::uint32_t{1} << static_cast<int>(r); }
  std::uint32_t bits_ = 0;
};

}  // namespace cc::harness
