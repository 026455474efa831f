// The signed distance between a triangle and an oriented box, with witness points (separation.h).
#pragma once

#include "collide/obb.h"
#include "collide/separation.h"
#include "collide/triangle.h"

namespace cc {

/// The signed distance between a closed triangle t and a closed box (the parallelepiped its axes
/// span): apart, their distance and a nearly closest pair, on_a on t and on_b on the box;
/// overlapping, minus the penetration depth (the length of the shortest translation of the box
/// that separates them), on_a a point of t and on_b one of the box's boundary with on_a - on_b
/// along that translation; touching, 0. Where closest pairs or shortest translations are not
/// unique (parallel faces or edges), any of them. Degenerate triangles are the segments or points
/// they are, flat boxes the rectangles, segments or points they are.
///  - Overlapping: the depth is the least overlap of the projections over the separating axes:
///    the box's axes, the triangle's normal and the cross products of its edges with the box's
///    axes (the normals of the faces of their difference). The edges are taken exactly from the
///    vertices and the cross products within 3 ulps per component, so a thin triangle or one far
///    from the origin measures its axes as well as any. An edge parallel to a box axis to within
///    about u of the size over the extent is left out: its face of the difference is a sliver of
///    width w, never nearer than its neighbours less w, and the widths join the bound. The
///    witnesses are the nearest pair between t's vertices farthest along the least axis and the
///    box's face, edge or corner nearest along it, the box's moved out along it.
///  - Apart, or too nearly touching to be sure they overlap: the nearest of each vertex of t
///    against the box, each corner of the box against t's face, and each pair of edges not
///    farther than the best so far; the bound is certified after the fact.
///  - Domain: finite inputs of magnitude at most 2^500, half extents >= 0, axes orthonormal to
///    within kObbOrthonormalTolerance. Outside it, NaN (separation.h). The bounds:
///    triangle_box_distance_bound.h.
Separation distance_triangle_obb(const Triangle& t, const Obb& box);

}  // namespace cc
