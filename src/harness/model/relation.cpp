#include "harness/model/relation.h"

namespace cc::harness {

std::string_view to_string(Relation r) {
  switch (r) {
    case Relation::swap_shapes: return "swap shapes";
    case Relation::permute_axes: return "permute axes";
    case Relation::flip_axis: return "flip an axis";
    case Relation::scale: return "scale by 2^k";
    case Relation::permute_vertices: return "reorder vertices";
    case Relation::permute_faces: return "reorder faces";
    case Relation::permute_points: return "reorder points";
    case Relation::permute_objects: return "reorder objects";
  }
  return "?";
}

}  // namespace cc::harness
