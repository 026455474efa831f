// The convex hull of a point set as the graph of its boundary, decided by exact orientation
// signs: what the hill-climbing update of a k-DOP walks (bvh_collide.h, BvUpdate::hill_climbing).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "collide/vec3.h"

namespace cc {

/// The boundary of the convex hull P of a point set, triangulated, as a graph on its vertices.
///  - `points`: the vertices of the triangulation, in the order of their first occurrence in the
///    input: every extreme point of the set once, and possibly points inside edges of P (one
///    swallowed by a later facet coplanar with its own); never a point inside a face of P or
///    inside P. So P is the convex hull of `points`.
///  - The neighbours of points[i] are neighbours[offsets[i]] .. neighbours[offsets[i + 1] - 1]
///    (indices into `points`): the other ends of the triangulation's edges at points[i]. P lies
///    in the cone from points[i] spanned by them, so a linear function that is not highest over
///    P at points[i] is higher at one of its neighbours (the graph holds every edge of P): a walk
///    that always climbs ends at the maximum, and from every point a climbing path leads to it.
///    Flat sets: the polygon's two neighbours (points on its edges dropped); collinear sets: the
///    two ends, each the other's neighbour; one point: none.
/// Every sign is decided exactly (orientation_sign, which decides every finite input);
/// std::nullopt when a coordinate is not finite. Repeated points count once; no points give an
/// empty graph.
struct HullGraph {
  std::vector<Vec3> points;
  std::vector<std::uint32_t> offsets;  // points.size() + 1 entries
  std::vector<std::uint32_t> neighbours;

  std::span<const std::uint32_t> neighbours_of(std::size_t i) const {
    return {neighbours.data() + offsets[i], offsets[i + 1] - offsets[i]};
  }
};

std::optional<HullGraph> hull_graph(std::span<const Vec3> points);

}  // namespace cc
