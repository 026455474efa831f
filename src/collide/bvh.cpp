// The parts every build strategy shares: laying out the tree and fitting its volumes.
#include "collide/bvh.h"

#include <iterator>

#include "collide/bvh_topology.h"
#include "collide/convex_hull.h"
#include "collide/hull_graph.h"
#include "collide/large_arrays.h"

namespace cc {

std::string_view to_string(BuildStrategy s) {
  switch (s) {
    case BuildStrategy::top_down: return "top_down";
    case BuildStrategy::bottom_up: return "bottom_up";
    case BuildStrategy::incremental: return "incremental";
    case BuildStrategy::lazy_top_down: return "lazy_top_down";
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
  reserve_large(t.nodes, tree.nodes.size());
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

// Appends to `out` points that include every vertex of the convex hull of `points`, each once:
// the vertices of fast_convex_hull, which leaves out only points certainly inside (`points` is
// sorted and its repeats dropped; `hull` is scratch).
void append_hull_points(std::vector<Vec3>& points, ConvexHull& hull, std::vector<Vec3>& out) {
  std::sort(points.begin(), points.end(), lexicographic_less);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() <= 4) {
    out.insert(out.end(), points.begin(), points.end());
    return;
  }
  fast_convex_hull(points, hull);
  for (std::uint32_t v : hull.vertices) out.push_back(points[v]);
}

// The hierarchy's arrays from a topology: the mesh's vertices, each slot's face, the nodes with
// their slots (volumes fitted later).
template <class BV>
Bvh<BV> lay_out(const Mesh& mesh, detail::Topology t) {
  Bvh<BV> bvh;
  bvh.order = std::move(t.order);
  reserve_large(bvh.vertices, mesh.vertices.size());
  bvh.vertices.assign(mesh.vertices.begin(), mesh.vertices.end());
  reserve_large(bvh.faces, bvh.order.size());
  for (std::uint32_t f : bvh.order) bvh.faces.push_back(mesh.faces[f]);
  reserve_large(bvh.nodes, t.nodes.size());
  bvh.nodes.resize(t.nodes.size());
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    BvhNode<BV>& n = bvh.nodes[i];
    n.left = t.nodes[i].left, n.right = t.nodes[i].right, n.first = t.nodes[i].first, n.count = t.nodes[i].count;
  }
  return bvh;
}

// The vertices of a node's triangles (appended to `out`).
template <class BV>
void append_vertices(const Bvh<BV>& bvh, const BvhNode<BV>& n, std::vector<Vec3>& out) {
  for (std::uint32_t s = n.first; s < n.first + n.count; ++s) {
    for (std::uint32_t v : bvh.faces[s]) out.push_back(bvh.vertices[v]);
  }
}

// Appends a node's hull points with their graph when `walkable` and hull_graph decides it (the
// graph's neighbours renumbered from the node's first point), else as append_hull_points does,
// with no graph. Returns whether the graph was made.
bool append_hull_graph(std::vector<Vec3>& points, bool walkable, ConvexHull& hull, NodePoints& out, NodeGraphs& graphs) {
  const auto first = static_cast<std::uint32_t>(out.points.size());
  const std::optional<HullGraph> g = walkable ? hull_graph(points) : std::nullopt;
  if (!g) {
    append_hull_points(points, hull, out.points);
  } else {
    out.points.insert(out.points.end(), g->points.begin(), g->points.end());
  }
  if (graphs.offsets.empty()) graphs.offsets.push_back(0);
  for (std::size_t i = first; i < out.points.size(); ++i) {
    if (g) {
      for (std::uint32_t n : g->neighbours_of(i - first)) graphs.neighbours.push_back(n);
    }
    graphs.offsets.push_back(static_cast<std::uint32_t>(graphs.neighbours.size()));
  }
  return g.has_value();
}

// A node of at most 4 k points gets no hull graph: moving its points (the exact update) costs
// less than its k walks would, each step of which evaluates every neighbour of a point.
template <class BV>
constexpr std::size_t kHullGraphAbove = 4 * 2 * kSlabDirections<BV>;

// Aabb and k-DOPs: leaves fitted to their vertices, other nodes merged from their children
// (which equals fitting their triangles, exactly). Every point of every volume lies in the
// root's box (its x, y, z slabs), whose farthest corner bounds the magnitude.
template <class BV>
void fit_refittable(Bvh<BV>& bvh, bool keep_hull_points, bool keep_hull_graphs) {
  using Traits = BoundingVolume<BV>;
  std::vector<Vec3> points;
  ConvexHull hull;
  keep_hull_points |= keep_hull_graphs;
  if (keep_hull_points) bvh.hull_points.range.resize(bvh.nodes.size());
  if (keep_hull_graphs) {
    bvh.hull_graphs.walkable.resize(bvh.nodes.size());
    bvh.hull_graphs.start.assign(bvh.nodes.size() * 2 * kSlabDirections<BV>, 0);
  }
  for (std::size_t i = bvh.nodes.size(); i-- > 0;) {
    BvhNode<BV>& n = bvh.nodes[i];
    points.clear();
    if (n.leaf()) {
      append_vertices(bvh, n, points);
      n.bv = Traits::fit(points);
    } else {
      n.bv = Traits::merge(bvh.nodes[n.left].bv, bvh.nodes[n.right].bv);
    }
    if (!keep_hull_points) continue;
    if (!n.leaf()) {
      for (std::int32_t child : {n.left, n.right}) {
        const auto c = bvh.hull_points.of(static_cast<std::size_t>(child));
        points.insert(points.end(), c.begin(), c.end());
      }
    }
    const auto first = static_cast<std::uint32_t>(bvh.hull_points.points.size());
    if (keep_hull_graphs) {
      bvh.hull_graphs.walkable[i] =
          append_hull_graph(points, points.size() > kHullGraphAbove<BV>, hull, bvh.hull_points, bvh.hull_graphs);
    } else {
      append_hull_points(points, hull, bvh.hull_points.points);
    }
    bvh.hull_points.range[i] = {first, static_cast<std::uint32_t>(bvh.hull_points.points.size()) - first};
  }
  bvh.hull_points.points.shrink_to_fit();
  bvh.hull_graphs.neighbours.shrink_to_fit();
  if (bvh.nodes.empty()) return;
  const BV& root = bvh.nodes[0].bv;
  double far[3];  // slabs 0, 1, 2 of a k-DOP are x, y, z
  for (int k = 0; k < 3; ++k) far[k] = std::max(std::fabs(root.lo[k]), std::fabs(root.hi[k]));
  bvh.magnitude = fp::sum3(far[0], far[1], far[2]);
}

// OBBs, children before parents: the node's convex hull by fast_convex_hull on its candidates,
// the distinct vertices its children kept (a leaf: of its triangles); the axes from the hull's
// surface (obb_axes), the extents over the candidates. fast_convex_hull keeps every point it
// does not certify inside the hull of those it keeps, so a node's vertices all lie in the hull
// of its candidates, and a box that holds the candidates holds them. In reverse pre-order a node
// comes right after its left subtree, which came right after its right subtree: the children's
// kept vertices are the last two sets on a stack, side by side. Every set is kept in
// lexicographic order, so a node's candidates are its children's sets merged (repeats dropped),
// without a sort.
void fit_obbs(Bvh<Obb>& bvh) {
  std::vector<Vec3> stack, candidates;
  std::vector<std::size_t> sizes;  // of the sets on the stack
  std::vector<char> on_hull;       // per candidate
  ConvexHull h;
  for (std::size_t i = bvh.nodes.size(); i-- > 0;) {
    BvhNode<Obb>& n = bvh.nodes[i];
    candidates.clear();
    if (n.leaf()) {
      append_vertices(bvh, n, candidates);
      std::sort(candidates.begin(), candidates.end(), lexicographic_less);
    } else {
      const std::size_t second = sizes.back();
      sizes.pop_back();
      const std::size_t first = sizes.back();
      sizes.pop_back();
      const auto end = stack.end(), middle = end - static_cast<std::ptrdiff_t>(second);
      std::merge(middle - static_cast<std::ptrdiff_t>(first), middle, middle, end, std::back_inserter(candidates),
                 lexicographic_less);
      stack.resize(stack.size() - first - second);
    }
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    const std::span<const Vec3> distinct = candidates;
    const std::optional<Mat3> flat =
        n.leaf() && distinct.size() == 3 ? triangle_axes(distinct[0], distinct[1], distinct[2]) : std::nullopt;
    std::size_t count = distinct.size();
    if (flat) {  // a triangle's hull: itself, every vertex kept
      n.bv = fit_obb(*flat, distinct);
      stack.insert(stack.end(), distinct.begin(), distinct.end());
    } else {
      fast_convex_hull(distinct, h);
      n.bv = fit_obb(obb_axes(distinct, h), distinct);
      on_hull.assign(distinct.size(), 0);
      for (std::uint32_t v : h.vertices) on_hull[v] = 1;
      count = 0;
      for (std::size_t v = 0; v < distinct.size(); ++v) {
        if (on_hull[v]) stack.push_back(distinct[v]), ++count;  // in the candidates' order
      }
    }
    sizes.push_back(count);
    // Every point of the box (the vertices among them) has norm1 at most that of its center plus
    // its half extents times their axes' norm1.
    const Obb& b = n.bv;
    const double reach = fp::sum3(b.half.x * norm1(b.axes.col[0]), b.half.y * norm1(b.axes.col[1]),
                                  b.half.z * norm1(b.axes.col[2]));
    bvh.magnitude = std::max(bvh.magnitude, norm1(b.center) + reach);
  }
}

// Spheres: each node's ball fitted to the vertices of its triangles (fit_sphere), not merged
// from its children's balls, which would widen up the tree. Every point of a ball has norm1 at
// most that of its centre plus sqrt(3) < 2 times its radius.
void fit_spheres(Bvh<Sphere>& bvh) {
  std::vector<Vec3> points;
  for (BvhNode<Sphere>& n : bvh.nodes) {
    points.clear();
    append_vertices(bvh, n, points);
    n.bv = fit_sphere(points);
    bvh.magnitude = std::max(bvh.magnitude, norm1(n.bv.center) + 2 * n.bv.radius);
  }
}

template <class BV>
Bvh<BV> fit(const Mesh& mesh, detail::Topology t, const BuildOptions& options) {
  Bvh<BV> bvh = lay_out<BV>(mesh, std::move(t));
  if constexpr (std::is_same_v<BV, Obb>) {
    fit_obbs(bvh);
  } else if constexpr (std::is_same_v<BV, Sphere>) {
    fit_spheres(bvh);
  } else {
    fit_refittable(bvh, options.hull_points, options.hull_graphs);
  }
  return bvh;
}

}  // namespace

template <class BV>
Bvh<BV> build_bvh(const Mesh& mesh, const BuildOptions& options) {
  switch (options.strategy) {
    case BuildStrategy::top_down:
    case BuildStrategy::lazy_top_down: return fit<BV>(mesh, detail::top_down_topology<BV>(mesh, options), options);
    case BuildStrategy::bottom_up: return fit<BV>(mesh, detail::layout(detail::bottom_up_tree<BV>(mesh)), options);
    case BuildStrategy::incremental:
      return fit<BV>(mesh, detail::layout(detail::incremental_tree<BV>(mesh)), options);
  }
  return {};
}

#define CC_INSTANTIATE(BV) template Bvh<BV> build_bvh<BV>(const Mesh&, const BuildOptions&);
CC_FOR_EACH_BOUNDING_VOLUME(CC_INSTANTIATE)
#undef CC_INSTANTIATE

}  // namespace cc
