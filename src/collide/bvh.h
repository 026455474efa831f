// Bounding-volume hierarchies over a triangle mesh: OBBTrees, k-DOP trees and AABB trees, built
// top-down, bottom-up or by incremental insertion.
#pragma once

#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "collide/bounding_volume.h"
#include "collide/mesh.h"

namespace cc {

enum class BuildStrategy {
  top_down,     // split the triangles recursively (split axis and point below)
  bottom_up,    // merge neighbouring nodes, level by level, pairing those whose merge is smallest
  incremental,  // insert triangles one at a time where the total volume grows least
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
  friend bool operator==(const BuildOptions&, const BuildOptions&) = default;
};

template <class BV>
struct BvhNode {
  BV bv;
  std::int32_t left = -1, right = -1;  // children (indices into Bvh::nodes), -1 for a leaf
  std::uint32_t first = 0, count = 0;  // the node's triangles: slots [first, first + count)
  bool leaf() const { return left < 0; }
};

/// Points kept per node to re-fit an Aabb or a k-DOP after a rotation: `range[node]` is a
/// [first, count) range of `points`.
struct NodePoints {
  std::vector<Vec3> points;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> range;
  std::span<const Vec3> of(std::size_t node) const { return {points.data() + range[node].first, range[node].second}; }
};

/// A binary hierarchy: nodes[0] is the root (no nodes for an empty mesh); every node's volume
/// contains, in exact arithmetic, every triangle of its slots. Triangle slot s holds
/// triangles[s], which is face order[s] of the mesh.
template <class BV>
struct Bvh {
  std::vector<BvhNode<BV>> nodes;
  std::vector<std::uint32_t> order;
  std::vector<Triangle> triangles;
  /// The largest norm1 of any vertex, corner or hull point the tree stores (for error bounds).
  double magnitude = 0;
  /// Aabb and k-DOP trees only (empty for Obb): per node, the corners of its volume (for the
  /// approximate update) and points among its triangles' vertices that include every vertex
  /// of their convex hull (for the exact update; all of them for small nodes).
  NodePoints corners, hull_points;
};

/// Builds the hierarchy of a valid mesh (see mesh_problem). Every strategy gives the same
/// kind of tree: binary, each triangle in exactly one leaf, each node's volume fitted to the
/// triangles below it (OBBs from their convex hull, see fit_obb).
template <class BV>
Bvh<BV> build_bvh(const Mesh& mesh, const BuildOptions& options);

}  // namespace cc
