// The signed distance between two oriented boxes, with witness points (separation.h).
#pragma once

#include "collide/obb.h"
#include "collide/separation.h"

namespace cc {

/// The signed distance between two closed boxes (the parallelepipeds their axes span): apart,
/// their distance and a nearly closest pair; overlapping, minus the penetration depth (the length
/// of the shortest translation of b that separates them), on_a a point of a's boundary and on_b
/// one of b's with on_a - on_b along that translation; touching, 0. Where closest pairs or
/// shortest translations are not unique (parallel faces or edges), any of them.
///  - Overlapping: the depth is the least overlap of the boxes' projections over the separating
///    axes (the faces' normals and the edges' cross products, the normals of the faces of their
///    difference a - b), each cross product within 2 ulps per component (a fused multiply-add),
///    so its direction is known to 4u however nearly parallel the edges are. An axis from edges
///    parallel to within about u of the size over the extent is left out: its face of a - b is
///    then a sliver of width w, never nearer than its neighbours less w, and w joins the bound. The witnesses are the nearest pair between a's and b's faces, edges or corners that
///    meet the least axis, b's moved out along it.
///  - Apart, or too nearly touching to be sure they overlap: the nearest of each corner against
///    the other box and each pair of edges not farther than the best so far; the bound is
///    certified after the fact (the witnesses above, the gap of the projections on their direction
///    and on every axis below).
///  - Domain: finite inputs of magnitude at most 2^500, half extents >= 0, axes orthonormal to
///    within kObbOrthonormalTolerance; flat boxes, segments and points are the shapes they are.
///    Outside it, NaN (separation.h). The bounds: obb_distance_bound.h.
Separation distance_obb_obb(const Obb& a, const Obb& b);

}  // namespace cc
