// Metamorphic relations: transformations of a query that leave the exact answer unchanged,
// and, by the library's construction (see collide/fp.h), its floating-point answer too. They
// need no oracle.
#pragma once

#include <optional>
#include <string_view>

#include "harness/input.h"

namespace cc::harness {

enum class Relation {
  swap_shapes,   // a with b (sphere, aabb, kdop, obb, tri_tri)
  permute_axes,  // x, y, z permuted (parameter: which of the 6 permutations)
  flip_axis,     // one coordinate negated, a mirror image (parameter: the axis)
  scale,         // every length multiplied by 2^parameter (ray: origin, direction and box)
};

std::string_view to_string(Relation r);

/// Whether the relation applies to queries of this kind at all: swapping needs two shapes of the
/// same kind; a mesh query takes only a permutation (of the world's axes: both poses' rows).
bool relation_applies(QueryKind kind, Relation relation);

/// The transformed query, or nothing when the relation does not apply: to its kind (see
/// relation_applies), or to this input: a k-DOP direction set not closed under the operation
/// (16 under both, 24 under flips), a scaling that would overflow, underflow or change a
/// value's precision.
std::optional<Input> transform(const Input& input, Relation relation, int parameter);

/// The query with every finite nonzero value outside [2^-250, 2^250] in magnitude replaced by 0:
/// on such inputs no intermediate product of the library reaches the subnormal range or
/// overflows, so scaling by 2^k for |k| <= 8 changes no rounding.
Input flush_extremes(const Input& input);

}  // namespace cc::harness
