// Triangles against boxes, by the separating-axis test.
#pragma once

#include "collide/aabb.h"
#include "collide/obb.h"
#include "collide/triangle.h"

namespace cc {

/// True when the closed triangle and the closed box share a point. Separating-axis test on the
/// 13 axes of Akenine-Moller: the 3 box axes, the triangle's normal, and the 9 cross products
/// of a box axis with a triangle edge.
///  - The box axes are exact (comparisons only). The other axes are certified: one separates
///    only when its gap exceeds a bound on the rounding error, so touching (at a face, an edge
///    or a vertex) is always reported, and a triangle apart from the box by less than 2^-44 of
///    the largest coordinate may be.
///  - Degenerate inputs are handled: a zero-area triangle (a segment or a point) and a box of
///    zero extent. When the 13 axes cannot be complete (a box of zero extent), the extra axes
///    of a flat or collinear configuration are tried as well.
///  - Domain: finite coordinates of magnitude at most 2^300, lo <= hi. NaN or infinite input, or
///    an inverted box: false.
bool test_triangle_aabb(const Triangle& t, const Aabb& box);

/// The same for an oriented box: the triangle is taken into the box's frame and tested as
/// above, with the rounding of that change of frame and the deviation of the box's axes from
/// orthonormal (see Obb) added to the error bound. A triangle apart from the box by less than
/// 2^-40 of the largest coordinate may be reported as touching.
///  - Domain: as above and as for Obb. NaN or infinite input, or a negative half extent: false.
bool test_triangle_obb(const Triangle& t, const Obb& box);

}  // namespace cc
