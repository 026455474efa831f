// The parts every build strategy shares: laying out the tree and fitting its volumes.
#include "collide/bvh.h"

#include "collide/bvh_topology.h"
#include "collide/convex_hull.h"
#include "collide/kdop_corners.h"

namespace cc {

std::string_view to_string(BuildStrategy s) {
  switch (s) {
    case BuildStrategy::top_down: return "top_down";
    case BuildStrategy::bottom_up: return "bottom_up";
    case BuildStrategy::incremental: return "incremental";
  }
  return "?";
}

std::string_view to_string(SplitAxis a) {
  switch (a) {
    case SplitAxis::longest_side: return "longest_side";
    case SplitAxis::splatter: return "splatter";
    case SplitAxis::min_sum: return "min_sum";
    case SplitAxis::min_max: return "min_max";
  }
  return "?";
}

std::string_view to_string(SplitPoint p) {
  switch (p) {
    case SplitPoint::midpoint: return "midpoint";
    case SplitPoint::mean: return "mean";
    case SplitPoint::median: return "median";
  }
  return "?";
}

namespace detail {

std::array<Vec3, 3> face_points(const Mesh& mesh, std::uint32_t face) { return mesh.triangle(face).v; }

Topology layout(const LinkedTree& tree) {
  Topology t;
  if (tree.root < 0) return t;
  struct Pending {
    std::int32_t linked;  // node of the linked tree
    std::int32_t parent;  // its parent in t, -1 for the root
  };
  for (std::vector<Pending> stack{{tree.root, -1}}; !stack.empty();) {
    const Pending p = stack.back();
    stack.pop_back();
    const auto n = static_cast<std::int32_t>(t.nodes.size());
    t.nodes.push_back({-1, -1, static_cast<std::uint32_t>(t.order.size()), 0});
    if (p.parent >= 0) (t.nodes[p.parent].left < 0 ? t.nodes[p.parent].left : t.nodes[p.parent].right) = n;
    const LinkedTree::Node& node = tree.nodes[p.linked];
    if (node.left < 0) {
      t.order.push_back(node.face);
    } else {
      stack.push_back({node.right, n});
      stack.push_back({node.left, n});
    }
  }
  // Pre-order: a node's slots end where the next node outside its subtree begins; count them
  // bottom-up.
  for (std::size_t i = t.nodes.size(); i-- > 0;) {
    auto& n = t.nodes[i];
    n.count = n.left < 0 ? 1 : t.nodes[n.left].count + t.nodes[n.right].count;
  }
  return t;
}

}  // namespace detail

namespace {

template <class BV>
constexpr bool kRefittable = !std::is_same_v<BV, Obb>;

constexpr std::size_t kKeepWhole = 64;

std::vector<Vec3> corners_of(const Aabb& b) {
  std::vector<Vec3> out;
  for (int i = 0; i < 8; ++i) out.push_back({(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z});
  return out;
}
template <int K>
std::vector<Vec3> corners_of(const Kdop<K>& d) {
  return kdop_corners(d);
}

void append(NodePoints& np, std::size_t node, std::span<const Vec3> points) {
  np.range[node] = {static_cast<std::uint32_t>(np.points.size()), static_cast<std::uint32_t>(points.size())};
  np.points.insert(np.points.end(), points.begin(), points.end());
}

// Fits every node's volume, children before parents. A node's hull comes from its children's
// hull points; Aabb and k-DOPs merge the children (which equals fitting their triangles,
// exactly); OBBs take axes from the node's hull and extents over all its triangles' vertices.
template <class BV>
Bvh<BV> fit(const Mesh& mesh, detail::Topology t) {
  using Traits = BoundingVolume<BV>;
  Bvh<BV> bvh;
  bvh.order = std::move(t.order);
  for (std::uint32_t f : bvh.order) {
    bvh.triangles.push_back(mesh.triangle(f));
    for (const Vec3& v : bvh.triangles.back().v) bvh.magnitude = std::max(bvh.magnitude, norm1(v));
  }
  bvh.nodes.resize(t.nodes.size());
  std::vector<std::vector<Vec3>> hull(t.nodes.size());
  const auto vertices_of = [&bvh](const BvhNode<BV>& n) {
    std::vector<Vec3> points;
    for (std::uint32_t s = n.first; s < n.first + n.count; ++s) {
      points.insert(points.end(), bvh.triangles[s].v.begin(), bvh.triangles[s].v.end());
    }
    return points;
  };
  for (std::size_t i = t.nodes.size(); i-- > 0;) {
    BvhNode<BV>& n = bvh.nodes[i];
    n.left = t.nodes[i].left, n.right = t.nodes[i].right, n.first = t.nodes[i].first, n.count = t.nodes[i].count;
    std::vector<Vec3> candidates = n.leaf() ? vertices_of(n) : hull[n.left];
    if (!n.leaf()) candidates.insert(candidates.end(), hull[n.right].begin(), hull[n.right].end());
    if constexpr (std::is_same_v<BV, Obb>) {
      const ConvexHull h = convex_hull(candidates);
      for (std::uint32_t v : h.vertices) hull[i].push_back(candidates[v]);
      n.bv = fit_obb(obb_axes(candidates, h), vertices_of(n));
      for (const Vec3& c : corners(n.bv)) bvh.magnitude = std::max(bvh.magnitude, norm1(c));
    } else {
      // The exact update needs a superset of the hull's vertices: small sets are kept whole,
      // larger ones pruned to their hull (Qhull costs more to start than a few points do).
      if (candidates.size() <= kKeepWhole) {
        hull[i] = std::move(candidates);
      } else {
        const ConvexHull h = convex_hull(candidates);
        for (std::uint32_t v : h.vertices) hull[i].push_back(candidates[v]);
      }
      n.bv = n.leaf() ? Traits::fit(hull[i]) : Traits::merge(bvh.nodes[n.left].bv, bvh.nodes[n.right].bv);
    }
  }
  if constexpr (kRefittable<BV>) {
    bvh.corners.range.resize(bvh.nodes.size());
    bvh.hull_points.range.resize(bvh.nodes.size());
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
      const std::vector<Vec3> c = corners_of(bvh.nodes[i].bv);
      for (const Vec3& p : c) bvh.magnitude = std::max(bvh.magnitude, norm1(p));
      append(bvh.corners, i, c);
      append(bvh.hull_points, i, hull[i]);
    }
  }
  return bvh;
}

}  // namespace

template <class BV>
Bvh<BV> build_bvh(const Mesh& mesh, const BuildOptions& options) {
  switch (options.strategy) {
    case BuildStrategy::top_down: return fit<BV>(mesh, detail::top_down_topology<BV>(mesh, options));
    case BuildStrategy::bottom_up: return fit<BV>(mesh, detail::layout(detail::bottom_up_tree<BV>(mesh)));
    case BuildStrategy::incremental: return fit<BV>(mesh, detail::layout(detail::incremental_tree<BV>(mesh)));
  }
  return {};
}

#define CC_INSTANTIATE(BV) template Bvh<BV> build_bvh<BV>(const Mesh&, const BuildOptions&);
CC_FOR_EACH_BOUNDING_VOLUME(CC_INSTANTIATE)
#undef CC_INSTANTIATE

}  // namespace cc
