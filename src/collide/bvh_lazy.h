// A hierarchy built lazily, the notes' lazy top-down building: at first only its root, and a node
// split (its children made and fitted) when a traversal first needs its children, so a query
// that prunes early builds a few nodes of a tree it would have paid for whole.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "collide/bvh.h"

namespace cc {

namespace detail {
template <class BV>
class TopDownSplitter;
}  // namespace detail

/// A top-down hierarchy whose nodes are made on demand. The splits are the eager top-down
/// build's (the same rules, the same ranges partitioned the same way), so once every node is
/// made the tree has the eager tree's nodes, in the order they were made instead of pre-order.
/// Each node is fitted to the vertices of its triangles when it is made:
///  - Aabb and k-DOP nodes are then the eager tree's bit for bit (a merge of children is the fit
///    of their union), and so is the magnitude (from the root), so collide() gives the eager
///    tree's answers exactly;
///  - Obb nodes (fit_obb on all the node's vertices, not on its children's hulls) and sphere nodes
///    (Ritter's ball depends on the order of the points, which later splits change) may differ
///    from the eager tree's; both contain their triangles, so the answers differ at most by pairs
///    within the leaf test's band. Their magnitude bounds every point of any node's volume by
///    16 times the mesh's largest vertex norm1 (a box or ball fitted to points lies within 8).
/// Hull points are never kept: the exact update moves every vertex of a node. Not thread safe:
/// a traversal makes nodes.
template <class BV>
class LazyBvh {
 public:
  /// The root, fitted to every triangle of a valid mesh (mesh_problem); the options' split axis,
  /// split point and leaf size as for build_bvh's top-down strategy (the strategy and
  /// hull_points are not used).
  LazyBvh(const Mesh& mesh, const BuildOptions& options);
  ~LazyBvh();
  LazyBvh(const LazyBvh&) = delete;
  LazyBvh& operator=(const LazyBvh&) = delete;

  /// The nodes made so far (nodes[0] the root, when the mesh has triangles); a node whose
  /// children are not made yet has left == kNotSplitYet. Slots outside the leaves made so far
  /// may still be reordered by later splits.
  const Bvh<BV>& tree() const { return tree_; }
  /// Makes the node's children if it has some and they are not made yet (then tree().nodes
  /// grows: references into it are invalidated). False for a leaf.
  bool split(std::int32_t node);
  /// How many nodes are made (the whole tree has the eager top-down tree's count).
  std::size_t nodes_made() const { return tree_.nodes.size(); }

 private:
  BvhNode<BV> make_node(std::uint32_t first, std::uint32_t count) const;

  Mesh mesh_;  // the splitter's (a copy: the caller's mesh need not outlive the tree)
  Bvh<BV> tree_;
  std::unique_ptr<detail::TopDownSplitter<BV>> splitter_;
  std::uint32_t leaf_size_ = 1;
};

}  // namespace cc
