// Metamorphic relations: transformations of a query that leave the exact answer unchanged,
// and, by the library's construction (see collide/fp.h), its floating-point answer too. They
// need no oracle.
#pragma once

#include <optional>
#include <string_view>

#include "harness/model/answer.h"
#include "harness/model/input.h"

namespace cc::harness {

enum class Relation {
  swap_shapes,       // a with b (sphere, aabb, kdop, obb, tri_tri)
  permute_axes,      // x, y, z permuted (parameter: which of the 6 permutations)
  flip_axis,         // one coordinate negated, a mirror image (parameter: the axis)
  scale,             // every length multiplied by 2^parameter (ray: origin, direction and box)
  permute_vertices,  // each triangle's vertices reordered (tri_*, and every face of a mesh)
  permute_faces,     // a mesh's faces reordered (mesh_*, ray_mesh): the answer's faces renamed
  permute_points,    // each k-DOP point set reordered
  permute_objects,   // a broadphase scene's slots reordered, in every frame: the pairs renamed
};

/// Every relation, in the order above.
inline constexpr Relation kAllRelations[] = {Relation::swap_shapes,      Relation::permute_axes,
                                             Relation::flip_axis,        Relation::scale,
                                             Relation::permute_vertices, Relation::permute_faces,
                                             Relation::permute_points,   Relation::permute_objects};

std::string_view to_string(Relation r);

/// Whether the relation applies to queries of this kind at all: swapping needs two shapes of the
/// same kind; a mesh query takes a permutation of the world's axes (both poses' rows), of its
/// faces and of their vertices; a ray against a mesh the last two; the reorderings apply to
/// what the kind has (triangles, faces, point sets, objects).
bool relation_applies(QueryKind kind, Relation relation);

/// The transformed query, or nothing when the relation does not apply: to its kind (see
/// relation_applies), or to this input: a k-DOP direction set not closed under the operation
/// (16 under both, 24 under flips), a scaling that would overflow, underflow or change a
/// value's precision. A reordering follows the parameter (any int): the triangle's vertex order
/// (one of 6, b's from parameter / 6 for tri_tri; face f of a mesh takes parameter + f), or the
/// seed of a shuffle of the faces, points or slots; a reordered mesh is given by its triangles.
std::optional<Input> transform(const Input& input, Relation relation, int parameter);

/// The answer the transformed query should get, from the answer to the original query: the same,
/// with the faces (mesh pairs, ray_mesh's face) or the slots (broadphase pairs) renamed by the
/// reordering, pairs sorted again.
Answer mapped_answer(const Answer& answer, const Input& original, Relation relation, int parameter);

/// The query with every finite nonzero value outside [2^-250, 2^250] in magnitude replaced by 0:
/// on such inputs no intermediate product of the library reaches the subnormal range or
/// overflows, so scaling by 2^k for |k| <= 8 changes no rounding.
Input flush_extremes(const Input& input);

}  // namespace cc::harness
