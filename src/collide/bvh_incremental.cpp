// Incremental insertion: the triangles are added one at a time, in mesh order. Each new leaf
// becomes the sibling of the node where the total volume of the tree grows least: the new
// parent's size plus the growth of every ancestor, found exactly by branch and bound (a node's
// subtree can only cost more than the leaf's own size plus the growth inherited so far).
#include <queue>

#include "collide/bvh_topology.h"

namespace cc::detail {

template <class BV>
LinkedTree incremental_tree(const Mesh& mesh) {
  using Traits = BoundingVolume<BV>;
  LinkedTree tree;
  std::vector<BV> volumes;
  std::vector<std::int32_t> parent;

  for (std::uint32_t f = 0; f < mesh.size(); ++f) {
    const auto points = face_points(mesh, f);
    const BV leaf_volume = Traits::fit(points);
    const auto leaf = static_cast<std::int32_t>(tree.nodes.size());
    tree.nodes.push_back({-1, -1, f});
    volumes.push_back(leaf_volume);
    parent.push_back(-1);
    if (tree.root < 0) {
      tree.root = leaf;
      continue;
    }

    // Branch and bound over candidate siblings.
    const BvSize leaf_size = Traits::size(leaf_volume);
    struct Candidate {
      BvSize bound;  // a lower bound of the cost of any node in this subtree
      BvSize inherited;
      std::int32_t node;
      bool operator<(const Candidate& o) const { return o.bound < bound; }  // smallest first
    };
    std::priority_queue<Candidate> queue;
    queue.push({leaf_size, {}, tree.root});
    std::int32_t best = tree.root;
    BvSize best_cost{INFINITY, INFINITY};
    while (!queue.empty()) {
      const Candidate c = queue.top();
      queue.pop();
      if (!(c.bound < best_cost)) break;
      const BvSize merged = Traits::size(Traits::merge(volumes[c.node], leaf_volume));
      const BvSize cost = merged + c.inherited;
      if (cost < best_cost) best_cost = cost, best = c.node;
      const LinkedTree::Node& n = tree.nodes[c.node];
      if (n.left >= 0) {
        const BvSize inherited = c.inherited + (merged - Traits::size(volumes[c.node]));
        const BvSize bound = leaf_size + inherited;
        if (bound < best_cost) {
          queue.push({bound, inherited, n.left});
          queue.push({bound, inherited, n.right});
        }
      }
    }

    // The new parent takes best's place.
    const auto joint = static_cast<std::int32_t>(tree.nodes.size());
    const std::int32_t above = parent[best];
    tree.nodes.push_back({best, leaf, 0});
    volumes.push_back(Traits::merge(volumes[best], leaf_volume));
    parent.push_back(above);
    parent[best] = joint, parent[leaf] = joint;
    if (above < 0) {
      tree.root = joint;
    } else {
      (tree.nodes[above].left == best ? tree.nodes[above].left : tree.nodes[above].right) = joint;
    }
    for (std::int32_t a = above; a >= 0; a = parent[a]) {
      volumes[a] = Traits::merge(volumes[tree.nodes[a].left], volumes[tree.nodes[a].right]);
    }
  }
  return tree;
}

#define CC_INSTANTIATE(BV) template LinkedTree incremental_tree<BV>(const Mesh&);
CC_FOR_EACH_BOUNDING_VOLUME(CC_INSTANTIATE)
#undef CC_INSTANTIATE

}  // namespace cc::detail
