#include "collide/bvh_lazy.h"

#include <algorithm>

#include "collide/bvh_topology.h"

namespace cc {

template <class BV>
LazyBvh<BV>::LazyBvh(const Mesh& mesh, const BuildOptions& options)
    : mesh_(mesh), splitter_(std::make_unique<detail::TopDownSplitter<BV>>(mesh_, options)),
      leaf_size_(static_cast<std::uint32_t>(std::max(options.leaf_size, 1))) {
  tree_.vertices = mesh.vertices;
  tree_.order.resize(mesh.size());
  tree_.faces.resize(mesh.size());
  for (std::uint32_t s = 0; s < mesh.size(); ++s) tree_.order[s] = s, tree_.faces[s] = mesh.faces[s];
  if (mesh.size() == 0) return;
  tree_.nodes.push_back(make_node(0, static_cast<std::uint32_t>(mesh.size())));
  if constexpr (std::is_same_v<BV, Obb> || std::is_same_v<BV, Sphere>) {
    double largest = 0;
    for (const Vec3& v : mesh.vertices) largest = std::max(largest, norm1(v));
    tree_.magnitude = 16 * largest;
  } else {  // as the eager build: the root's box bounds every point of every volume
    const BV& root = tree_.nodes[0].bv;
    double far[3];
    for (int k = 0; k < 3; ++k) far[k] = std::max(std::fabs(root.lo[k]), std::fabs(root.hi[k]));
    tree_.magnitude = fp::sum3(far[0], far[1], far[2]);
  }
}

template <class BV>
LazyBvh<BV>::~LazyBvh() = default;

template <class BV>
BvhNode<BV> LazyBvh<BV>::make_node(std::uint32_t first, std::uint32_t count) const {
  std::vector<Vec3> points;
  points.reserve(3 * count);
  for (std::uint32_t s = first; s < first + count; ++s) {
    for (std::uint32_t v : tree_.faces[s]) points.push_back(tree_.vertices[v]);
  }
  BvhNode<BV> n;
  n.bv = BoundingVolume<BV>::fit(points);
  n.first = first, n.count = count;
  n.left = count <= leaf_size_ ? -1 : kNotSplitYet;
  return n;
}

template <class BV>
bool LazyBvh<BV>::split(std::int32_t node) {
  BvhNode<BV>& n = tree_.nodes[node];
  if (n.left != kNotSplitYet) return n.left >= 0;
  const std::uint32_t first = n.first, count = n.count;
  const std::uint32_t left = splitter_->split(first, count);
  for (std::uint32_t s = first; s < first + count; ++s) {
    tree_.order[s] = splitter_->face(s);
    tree_.faces[s] = mesh_.faces[tree_.order[s]];
  }
  const BvhNode<BV> a = make_node(first, left), b = make_node(first + left, count - left);
  const auto at = static_cast<std::int32_t>(tree_.nodes.size());
  tree_.nodes.push_back(a);
  tree_.nodes.push_back(b);
  tree_.nodes[node].left = at, tree_.nodes[node].right = at + 1;
  return true;
}

#define CC_INSTANTIATE(BV) template class LazyBvh<BV>;
CC_FOR_EACH_BOUNDING_VOLUME(CC_INSTANTIATE)
#undef CC_INSTANTIATE

}  // namespace cc
