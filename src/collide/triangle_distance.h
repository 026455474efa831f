// The distance between two triangles, with witness points (separation.h).
#pragma once

#include "collide/separation.h"
#include "collide/triangle.h"

namespace cc {

/// The distance between two closed triangles (never negative: triangles have no inside; 0 where
/// they meet) and a nearly closest pair, on_a on a and on_b on b. Where closest pairs are not unique
/// (parallel faces or edges), any of them. Degenerate triangles are the segments or points they
/// are.
///  - The witnesses are among the candidates a closest pair is among: each vertex against the
///    other triangle, each pair of edges, and each edge's crossing of the other triangle; the
///    first a test proves closest (witnesses that meet, a lowest vertex over the other face, an
///    edge pair whose direction leaves both triangles behind its witnesses), else the nearest.
///    The bound is certified after the fact, as for segments (segment_distance.h): the
///    witnesses' distance above, the gap between the triangles' projections on the witnesses'
///    direction or their features' normal below.
///  - Domain: finite inputs of magnitude at most 2^500; outside it, NaN (separation.h).
///    point_error: 32u of the largest vertex coordinate, plus the subnormal slack.
///  - Thin or tiny triangles (nearly collinear vertices; features below about 2^-250 of the
///    pair's extent, where products of four underflow): every witness is still a point of its
///    triangle within point_error (taken in the triangle's own coordinates, its parameters
///    clamped to it), and the bound still holds, but the witnesses may be far from closest and
///    the bound loose.
Separation distance_triangle_triangle(const Triangle& a, const Triangle& b);

/// A certified lower bound on the distance between a and b from one direction: the gap between
/// their projections on it over its length, less its rounding bound; 0 where they overlap on it.
double triangle_gap_along(const Triangle& a, const Triangle& b, const Vec3& direction);

}  // namespace cc
