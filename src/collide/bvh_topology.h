// The shape of a hierarchy before its volumes are fitted: what each build strategy decides.
// Internal to the hierarchy builders (bvh_*.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "collide/bvh.h"

namespace cc::detail {

/// Nodes in depth-first pre-order (the root first, a node before its children, so children
/// have larger indices), each with its slots [first, first + count); order[s] is the mesh face
/// in slot s.
struct Topology {
  struct Node {
    std::int32_t left = -1, right = -1;
    std::uint32_t first = 0, count = 0;
  };
  std::vector<Node> nodes;
  std::vector<std::uint32_t> order;
};

/// A binary tree over single triangles as the bottom-up and incremental builders make it:
/// leaves carry a face, nodes are in any order, `root` names the root.
struct LinkedTree {
  struct Node {
    std::int32_t left = -1, right = -1;
    std::uint32_t face = 0;  // leaves only
  };
  std::vector<Node> nodes;
  std::int32_t root = -1;
};

/// Lays out a linked tree in depth-first pre-order, so every subtree's faces are contiguous.
Topology layout(const LinkedTree& tree);

/// The points of a face.
std::array<Vec3, 3> face_points(const Mesh& mesh, std::uint32_t face);

template <class BV>
Topology top_down_topology(const Mesh& mesh, const BuildOptions& options);

template <class BV>
class TopDownImpl;

/// Top-down splitting, one node at a time (what top_down_topology does for every node): the
/// mesh's triangles in an array of slots, in face order at first; split() partitions a node's
/// range of it in place as the eager build does, so the same ranges split the same way.
template <class BV>
class TopDownSplitter {
 public:
  TopDownSplitter(const Mesh& mesh, const BuildOptions& options);
  ~TopDownSplitter();
  /// Reorders slots [first, first + count), count >= 2, so that the first `returned` of them
  /// go to the left child; the return value lies in (0, count).
  std::uint32_t split(std::uint32_t first, std::uint32_t count);
  /// The mesh face in a slot.
  std::uint32_t face(std::uint32_t slot) const;
  std::uint32_t size() const;

 private:
  std::unique_ptr<TopDownImpl<BV>> impl_;
};
template <class BV>
LinkedTree bottom_up_tree(const Mesh& mesh);
template <class BV>
LinkedTree incremental_tree(const Mesh& mesh);

}  // namespace cc::detail
