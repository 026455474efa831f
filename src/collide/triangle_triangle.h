// Triangle against triangle, by the separating-axis test.
#pragma once

#include "collide/triangle.h"

namespace cc {

/// True when the closed triangles share a point. Separating-axis test on the 2 normals and the
/// 9 cross products of an edge of each; when those cannot be complete (coplanar triangles, or
/// both degenerate) also on the in-plane normals and the axes of collinear and single-point
/// configurations.
///  - Certified: an axis separates only when its gap exceeds a bound on the rounding error, so
///    touching (at a vertex, an edge or a face) is always reported, and triangles apart by less
///    than 2^-44 of the largest coordinate (in the conditioning of the deciding axis) may be.
///  - Degenerate triangles (segments, points) and coplanar triangles are handled exactly as
///    above. Symmetric in a and b bit for bit.
///  - Domain: finite coordinates of magnitude at most 2^300. NaN or infinite input: false.
bool test_triangle_triangle(const Triangle& a, const Triangle& b);

}  // namespace cc
