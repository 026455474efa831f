// Top-down building: fit a volume to a node's triangles, split them along one axis of its
// frame, recurse. Gottschalk's OBBTree is longest_side + midpoint with one triangle per leaf;
// Klosowski's k-DOP trees choose the axis by min_sum, min_max, splatter or longest_side.
#include <algorithm>
#include <numeric>
#include <span>

#include "collide/bvh_topology.h"

namespace cc::detail {
namespace {

template <class BV>
class TopDown {
 public:
  TopDown(const Mesh& mesh, const BuildOptions& options) : mesh_(mesh), options_(options) {
    for (std::uint32_t f = 0; f < mesh.size(); ++f) centroids_.push_back(centroid(mesh, f));
  }

  Topology build() {
    Topology t;
    t.order.resize(mesh_.size());
    std::iota(t.order.begin(), t.order.end(), 0u);
    if (mesh_.size() == 0) return t;
    t.nodes.push_back({-1, -1, 0, static_cast<std::uint32_t>(mesh_.size())});
    for (std::vector<std::int32_t> unsplit{0}; !unsplit.empty();) {
      const std::int32_t n = unsplit.back();
      unsplit.pop_back();
      if (split_node(t, n)) unsplit.insert(unsplit.end(), {t.nodes[n].left, t.nodes[n].right});
    }
    return reorder(t);
  }

 private:
  using Traits = BoundingVolume<BV>;

  using Faces = std::span<std::uint32_t>;

  BV fit_faces(std::span<const std::uint32_t> faces) const {
    std::vector<Vec3> points;
    points.reserve(3 * faces.size());
    for (std::uint32_t f : faces) {
      const auto p = face_points(mesh_, f);
      points.insert(points.end(), p.begin(), p.end());
    }
    return Traits::fit(points);
  }

  double projection(std::uint32_t face, const Vec3& axis) const { return dot(centroids_[face], axis); }

  // Reorders the faces so that the first ones lie before the split point along `axis`; returns
  // how many, in (0, size). Falls back to the median when the point leaves one side empty
  // (all centroids on one side, or all equal: then the halves are arbitrary).
  std::uint32_t split(Faces faces, const Vec3& axis, double midpoint) const {
    const auto count = static_cast<std::uint32_t>(faces.size());
    const auto begin = faces.begin(), end = faces.end();
    const auto less = [&](std::uint32_t a, std::uint32_t b) { return projection(a, axis) < projection(b, axis); };
    double at = midpoint;
    if (options_.point == SplitPoint::mean) {
      double sum = 0;
      for (auto it = begin; it != end; ++it) sum += projection(*it, axis);
      at = sum / count;
    }
    if (options_.point != SplitPoint::median) {
      const auto middle = std::partition(begin, end, [&](std::uint32_t f) { return projection(f, axis) < at; });
      const auto left = static_cast<std::uint32_t>(middle - begin);
      if (left > 0 && left < count) return left;
    }
    const std::uint32_t half = count / 2;
    std::nth_element(begin, begin + half, end, less);
    return half;
  }

  int choose_axis(Faces faces, const BV& bv) const {
    const Mat3 axes = Traits::axes(bv);
    const Vec3 half = Traits::half(bv);
    switch (options_.axis) {
      case SplitAxis::longest_side:
        return half.x >= half.y && half.x >= half.z ? 0 : (half.y >= half.z ? 1 : 2);
      case SplitAxis::splatter: {
        int best = 0;
        double best_variance = -1;
        for (int k = 0; k < 3; ++k) {
          double sum = 0, sum2 = 0;
          for (std::uint32_t f : faces) {
            const double p = projection(f, axes.col[k]);
            sum += p, sum2 += p * p;
          }
          const double n = static_cast<double>(faces.size());
          const double variance = sum2 / n - (sum / n) * (sum / n);
          if (variance > best_variance) best_variance = variance, best = k;
        }
        return best;
      }
      case SplitAxis::min_sum:
      case SplitAxis::min_max: {
        int best = 0;
        BvSize best_cost{INFINITY, INFINITY};
        for (int k = 0; k < 3; ++k) {
          std::vector<std::uint32_t> trial(faces.begin(), faces.end());
          const std::uint32_t left = split(trial, axes.col[k], midpoint_along(bv, k));
          const BvSize a = Traits::size(fit_faces(std::span(trial).first(left)));
          const BvSize b = Traits::size(fit_faces(std::span(trial).subspan(left)));
          const BvSize cost = options_.axis == SplitAxis::min_sum ? a + b : std::max(a, b);
          if (cost < best_cost) best_cost = cost, best = k;
        }
        return best;
      }
    }
    return 0;
  }

  static double midpoint_along(const BV& bv, int k) { return dot(Traits::center(bv), Traits::axes(bv).col[k]); }

  // Splits node n into two children, or returns false when it is a leaf.
  bool split_node(Topology& t, std::int32_t n) {
    const std::uint32_t first = t.nodes[n].first, count = t.nodes[n].count;
    if (count <= static_cast<std::uint32_t>(std::max(options_.leaf_size, 1))) return false;
    const Faces faces = std::span(t.order).subspan(first, count);
    const BV bv = fit_faces(faces);
    const int k = choose_axis(faces, bv);
    const std::uint32_t left = split(faces, Traits::axes(bv).col[k], midpoint_along(bv, k));
    const auto l = static_cast<std::int32_t>(t.nodes.size());
    t.nodes.push_back({-1, -1, first, left});
    t.nodes.push_back({-1, -1, first + left, count - left});
    t.nodes[n].left = l, t.nodes[n].right = l + 1;
    return true;
  }

  // The nodes were created parent first but siblings side by side; renumber them in pre-order.
  static Topology reorder(const Topology& t) {
    Topology out;
    out.order = t.order;
    std::vector<std::int32_t> stack{0};
    std::vector<std::int32_t> renumbered(t.nodes.size(), -1);
    std::vector<std::int32_t> visit;
    while (!stack.empty()) {
      const std::int32_t n = stack.back();
      stack.pop_back();
      renumbered[n] = static_cast<std::int32_t>(visit.size());
      visit.push_back(n);
      if (t.nodes[n].left >= 0) stack.push_back(t.nodes[n].right), stack.push_back(t.nodes[n].left);
    }
    for (std::int32_t n : visit) {
      Topology::Node node = t.nodes[n];
      if (node.left >= 0) node.left = renumbered[node.left], node.right = renumbered[node.right];
      out.nodes.push_back(node);
    }
    return out;
  }

  const Mesh& mesh_;
  BuildOptions options_;
  std::vector<Vec3> centroids_;
};

}  // namespace

template <class BV>
Topology top_down_topology(const Mesh& mesh, const BuildOptions& options) {
  return TopDown<BV>(mesh, options).build();
}

#define CC_INSTANTIATE(BV) template Topology top_down_topology<BV>(const Mesh&, const BuildOptions&);
CC_FOR_EACH_BOUNDING_VOLUME(CC_INSTANTIATE)
#undef CC_INSTANTIATE

}  // namespace cc::detail
