// Bounding-volume hierarchies over a triangle mesh: OBBTrees, k-DOP trees, AABB trees and sphere
// trees, built top-down, bottom-up or by incremental insertion.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "collide/bounding_volume.h"
#include "collide/mesh.h"

namespace cc {

enum class BuildStrategy {
  top_down,       // split the triangles recursively (split axis and point below)
  bottom_up,      // merge neighbouring nodes, level by level, pairing those whose merge is smallest
  incremental,    // insert triangles one at a time where the total volume grows least
  lazy_top_down,  // top-down, a node split on first visit (LazyBvh, bvh_lazy.h); build_bvh makes
                  // the whole tree at once: the top-down tree
};

/// Top-down: which axis of the node's frame (BoundingVolume<BV>::axes) to split along.
enum class SplitAxis {
  longest_side,  // the longest extent (Gottschalk's OBBTree rule)
  splatter,      // the largest variance of the triangle centroids' projections (Klosowski)
  min_sum,       // the axis whose split minimises the sum of the children's sizes (Klosowski)
  min_max,       // the axis whose split minimises the larger child's size (Klosowski)
};

/// Top-down: where along the axis to split the triangles (by their centroids).
enum class SplitPoint {
  midpoint,  // the middle of the node's extent (Gottschalk)
  mean,      // the mean of the centroids
  median,    // the median centroid: equal halves
};

std::string_view to_string(BuildStrategy s);
std::string_view to_string(SplitAxis a);
std::string_view to_string(SplitPoint p);

struct BuildOptions {
  BuildStrategy strategy = BuildStrategy::top_down;
  SplitAxis axis = SplitAxis::longest_side;
  SplitPoint point = SplitPoint::midpoint;
  /// Top-down: a node with at most this many triangles is a leaf (OBBTree: 1; k-DOP trees
  /// keep a few). Bottom-up and incremental trees have one triangle per leaf.
  int leaf_size = 1;
  /// Aabb and k-DOP trees: also keep, per node, points that include every vertex of the convex
  /// hull of its triangles (Bvh::hull_points), which the exact update moves. Without them the
  /// exact update moves every vertex of the node's triangles (the same volume, more work).
  bool hull_points = false;
  /// Aabb and k-DOP trees: also keep, per node of more than 4 k hull point candidates (its
  /// triangles' vertices, or its children's hull points), the graph of the exact convex hull of
  /// its triangles (Bvh::hull_graphs, from hull_graph), which the hill-climbing update walks.
  /// Implies hull_points, which for those nodes are the graph's points: every vertex of the
  /// hull, no point inside it.
  bool hull_graphs = false;
  friend bool operator==(const BuildOptions&, const BuildOptions&) = default;
};

/// BvhNode::left of a node of a lazy hierarchy (bvh_lazy.h) that has children not made yet.
inline constexpr std::int32_t kNotSplitYet = -2;

template <class BV>
struct BvhNode {
  BV bv;
  std::int32_t left = -1, right = -1;  // children (indices into Bvh::nodes), -1 for a leaf
  std::uint32_t first = 0, count = 0;  // the node's triangles: slots [first, first + count)
  bool leaf() const { return left == -1; }
};

/// Points kept per node to re-fit an Aabb or a k-DOP after a rotation: `range[node]` is a
/// [first, count) range of `points`.
struct NodePoints {
  std::vector<Vec3> points;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> range;
  std::span<const Vec3> of(std::size_t node) const { return {points.data() + range[node].first, range[node].second}; }
};

/// The slab directions of the k-DOP an Aabb or k-DOP node is re-fitted as under rotation: 3 for
/// an Aabb (the 6-DOP), k / 2 for a k-DOP (an Obb or a ball is moved whole and uses none).
template <class BV>
inline constexpr int kSlabDirections = 3;
template <int K>
inline constexpr int kSlabDirections<Kdop<K>> = K / 2;

/// Per node, the graph of its hull points (hull_graph.h), for the hill-climbing update. Indices
/// of points are those of NodePoints::points; a neighbour is an index within the node's range.
struct NodeGraphs {
  std::vector<std::uint32_t> offsets;     // per point, and one past the last: its neighbours start there
  std::vector<std::uint32_t> neighbours;  // within the node's range
  std::vector<std::uint8_t> walkable;     // per node: 1 when it has a graph, else 0 (small, or undecided)
  /// Per node, two per slab direction (the upper end, then the lower): the point (within the
  /// node's range) where the last walk for it ended, where the next one starts. Written by
  /// collide() under BvUpdate::hill_climbing through relaxed atomic stores, so queries on one tree
  /// may run concurrently: any value read is a valid start and the answer does not depend on it.
  mutable std::vector<std::uint32_t> start;
  std::span<const std::uint32_t> neighbours_of(std::size_t point) const {
    return {neighbours.data() + offsets[point], offsets[point + 1] - offsets[point]};
  }
};

/// A binary hierarchy: nodes[0] is the root (no nodes for an empty mesh), every node before
/// its children (depth-first pre-order, so node n's left child is n + 1); every node's volume
/// contains, in exact arithmetic, every triangle of its slots. Triangle slot s is face order[s]
/// of the mesh, stored as its three indices into `vertices` (a copy of the mesh's).
template <class BV>
struct Bvh {
  std::vector<BvhNode<BV>> nodes;
  std::vector<std::uint32_t> order;
  std::vector<std::array<std::uint32_t, 3>> faces;  // per slot
  std::vector<Vec3> vertices;
  /// At least the norm1 of every vertex, hull point and point of any node's volume (for error
  /// bounds).
  double magnitude = 0;
  /// Only when built with BuildOptions::hull_points (Aabb and k-DOP trees), else empty: per node,
  /// points among its triangles' vertices that include every vertex of their convex hull (all
  /// of them for small nodes).
  NodePoints hull_points;
  /// Only when built with BuildOptions::hull_graphs, else empty.
  NodeGraphs hull_graphs;

  Triangle triangle(std::size_t slot) const {
    const auto& f = faces[slot];
    return {{vertices[f[0]], vertices[f[1]], vertices[f[2]]}};
  }
};

/// Builds the hierarchy of a valid mesh (see mesh_problem). Every strategy gives the same
/// kind of tree: binary, each triangle in exactly one leaf, each node's volume fitted to the
/// triangles below it (Aabb and k-DOPs the smallest; OBBs with the axes of the convex hull of
/// the node's triangles, as fit_obb, and extents over their vertices; spheres as fit_sphere on
/// their vertices). The convex hull of a
/// node comes from its children's hull points, never from all of its triangles.
template <class BV>
Bvh<BV> build_bvh(const Mesh& mesh, const BuildOptions& options);

}  // namespace cc
