// Metamorphic relations: transformations of a query that leave the exact answer unchanged,
// and, by the library's construction (see collide/fp.h), its floating-point answer too. They
// need no oracle.
#pragma once

#include <optional>
#include <string_view>

#include "harness/model/relation.h"
#include "harness/model/answer.h"
#include "harness/model/input.h"

namespace cc::harness {

/// Whether the relation applies to queries of this kind at all (its unit's relations).
bool relation_applies(QueryKind kind, Relation relation);

/// The transformed query, or nothing when the relation does not apply: to its kind (see
/// relation_applies), or to this input (the unit's admits(): a k-DOP direction set not closed
/// under the operation), a scaling that would overflow, underflow or change a value's precision.
/// The relations act on the parts of the input by their types (model/fields.h); swapping
/// exchanges the fields a and b. A reordering follows the parameter (any int): the i-th
/// triangle's vertex order is one of 6 by parameter / 6^i, face f of a mesh takes parameter + f;
/// the i-th mesh or point set, the slots of boxes over frames and a list of parts (walls) are
/// shuffled from it; the i-th wall's ends are swapped by a bit of its hash; a reordered mesh is
/// given by its triangles. In the plane of a disc and walls, permuting the axes swaps x and y
/// when the permutation puts y before x, and flipping z changes nothing.
std::optional<Input> transform(const Input& input, Relation relation, int parameter);

/// The answer the transformed query should get, from the answer to the original query: the same,
/// with the faces (the i-th mesh's, in the i-th place of every pair), the slots (of every
/// frame's pairs) or the parts of a list (walls, the first of every pair) renamed by the
/// reordering, pairs sorted again.
Answer mapped_answer(const Answer& answer, const Input& original, Relation relation, int parameter);

/// The query with every finite nonzero value outside [2^-250, 2^250] in magnitude replaced by 0:
/// on such inputs no intermediate product of the library reaches the subnormal range or
/// overflows, so scaling by 2^k for |k| <= 8 changes no rounding.
Input flush_extremes(const Input& input);

}  // namespace cc::harness
