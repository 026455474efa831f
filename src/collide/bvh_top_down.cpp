// Top-down building: find a node's frame and extent, split its triangles along one axis of the
// frame, recurse. A split sees each triangle as its centroid: the frame (for OBB trees the
// principal axes of the centroids), the extent (the centroids' least and greatest projections)
// and the side of the split point are the centroids'. The triangles are kept in one array (their
// centroids and faces) and each split partitions the node's range of it in place, so a level of
// the tree costs one or two passes over the triangles. Gottschalk's OBBTree is longest_side +
// midpoint with one triangle per leaf; Klosowski's k-DOP trees choose the axis by min_sum,
// min_max, splatter or longest_side.
#include <algorithm>
#include <span>

#include "collide/bvh_topology.h"
#include "collide/large_arrays.h"

namespace cc::detail {
namespace {

// x . y summed in order: a split is a heuristic (any split gives a valid tree), and the
// projections are its most frequent operations, so they skip fp::sum3's symmetry.
double projection(const Vec3& x, const Vec3& y) { return x.x * y.x + x.y * y.y + x.z * y.z; }

// A triangle being sorted into the tree.
struct Item {
  Vec3 centroid;  // rounded, as (1/3) (v0 + v1 + v2)
  std::uint32_t face;
};

// Where a node's centroids (or, for the sizes of min_sum and min_max, its vertices) lie in a
// frame: the frame's axes, and the least and greatest projection on each.
struct Extent {
  Mat3 axes;
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  double midpoint(int k) const { return 0.5 * (lo[k] + hi[k]); }
  BvSize size() const { return box_size(0.5 * (hi - lo)); }
  [[gnu::always_inline]] void add(const Vec3& p) {
    const Vec3 s{projection(axes.col[0], p), projection(axes.col[1], p), projection(axes.col[2], p)};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], s[k]), hi[k] = std::max(hi[k], s[k]);
  }
};

}  // namespace

template <class BV>
class TopDownImpl {
 public:
  TopDownImpl(const Mesh& mesh, const BuildOptions& options) : mesh_(mesh), options_(options) {
    reserve_large(items_, mesh.size());
    for (std::uint32_t f = 0; f < mesh.size(); ++f) {
      const Triangle t = mesh.triangle(f);
      items_.push_back({(1.0 / 3) * (t.v[0] + t.v[1] + t.v[2]), f});
    }
  }

  // Nodes in depth-first pre-order: a node is split as soon as it is made, its left child is
  // made next.
  Topology build() {
    Topology t;
    reserve_large(t.nodes, 2 * items_.size());  // every split leaves both parts non-empty: at most 2n - 1 nodes
    struct Pending {
      std::uint32_t first, count;
      std::int32_t parent;
    };
    const auto leaf_size = static_cast<std::uint32_t>(std::max(options_.leaf_size, 1));
    std::vector<Pending> stack;
    if (!items_.empty()) stack.push_back({0, static_cast<std::uint32_t>(items_.size()), -1});
    while (!stack.empty()) {
      const Pending p = stack.back();
      stack.pop_back();
      const auto n = static_cast<std::int32_t>(t.nodes.size());
      t.nodes.push_back({-1, -1, p.first, p.count});
      if (p.parent >= 0) (t.nodes[p.parent].left < 0 ? t.nodes[p.parent].left : t.nodes[p.parent].right) = n;
      if (p.count <= leaf_size) continue;
      const std::uint32_t left = split_node(std::span(items_).subspan(p.first, p.count));
      stack.push_back({p.first + left, p.count - left, n});
      stack.push_back({p.first, left, n});
    }
    t.order.reserve(items_.size());
    for (const Item& item : items_) t.order.push_back(item.face);
    return t;
  }

  std::uint32_t split_range(std::uint32_t first, std::uint32_t count) {
    return split_node(std::span(items_).subspan(first, count));
  }
  std::uint32_t face(std::uint32_t slot) const { return items_[slot].face; }
  std::uint32_t size() const { return static_cast<std::uint32_t>(items_.size()); }

 private:
  using Items = std::span<Item>;
  static constexpr bool kObb = std::is_same_v<BV, Obb>;

  // Aabb and k-DOPs: the coordinate axes (the x, y, z slabs of a k-DOP are its box). Obb: the
  // principal axes of the centroids (their covariance), which cost one pass; the node's own box,
  // fitted later from its convex hull, is not known before its children.
  Mat3 frame_of(std::span<const Item> items) const {
    if constexpr (!kObb) {
      return Mat3::identity();
    } else {
      const Vec3 origin = items[0].centroid;
      Vec3 sum{0, 0, 0};
      std::array<double, 6> square{};  // xx, yy, zz, xy, yz, zx
      for (const Item& item : items) {
        const Vec3 d = item.centroid - origin;
        sum = sum + d;
        square[0] += d.x * d.x, square[1] += d.y * d.y, square[2] += d.z * d.z;
        square[3] += d.x * d.y, square[4] += d.y * d.z, square[5] += d.z * d.x;
      }
      const double n = static_cast<double>(items.size());
      const Vec3 mean = (1 / n) * sum;
      return principal_axes({square[0] / n - mean.x * mean.x, square[1] / n - mean.y * mean.y,
                             square[2] / n - mean.z * mean.z, square[3] / n - mean.x * mean.y,
                             square[4] / n - mean.y * mean.z, square[5] / n - mean.z * mean.x});
    }
  }

  // The centroids' extent in the frame.
  static Extent extent_of(std::span<const Item> items, const Mat3& axes) {
    Extent e{axes};
    for (const Item& item : items) {
      if constexpr (kObb) {
        e.add(item.centroid);
      } else {
        for (int k = 0; k < 3; ++k) e.lo[k] = std::min(e.lo[k], item.centroid[k]), e.hi[k] = std::max(e.hi[k], item.centroid[k]);
      }
    }
    return e;
  }

  // The vertices' extent in the frame: the size of a child's box, for min_sum and min_max.
  Extent vertex_extent(std::span<const Item> items, const Mat3& axes) const {
    Extent e{axes};
    for (const Item& item : items) {
      for (const Vec3& v : mesh_.triangle(item.face).v) e.add(v);
    }
    return e;
  }

  static double projection(const Item& item, const Vec3& axis) { return detail::projection(item.centroid, axis); }

  // Reorders the items so that the first ones lie before the split point along `axis`; returns
  // how many, in (0, size). Falls back to the median when the point leaves one side empty
  // (all centroids on one side, or all equal: then the halves are arbitrary).
  std::uint32_t split(Items items, const Vec3& axis, double midpoint) const {
    const auto count = static_cast<std::uint32_t>(items.size());
    double at = midpoint;
    if (options_.point == SplitPoint::mean) {
      double sum = 0;
      for (const Item& item : items) sum += projection(item, axis);
      at = sum / count;
    }
    if (options_.point != SplitPoint::median) {
      const auto middle = std::partition(items.begin(), items.end(), [&](const Item& i) { return projection(i, axis) < at; });
      const auto left = static_cast<std::uint32_t>(middle - items.begin());
      if (left > 0 && left < count) return left;
    }
    const std::uint32_t half = count / 2;
    std::nth_element(items.begin(), items.begin() + half, items.end(),
                     [&](const Item& a, const Item& b) { return projection(a, axis) < projection(b, axis); });
    return half;
  }

  int choose_axis(Items items, const Extent& e) const {
    switch (options_.axis) {
      case SplitAxis::longest_side: {
        const Vec3 half = 0.5 * (e.hi - e.lo);
        return half.x >= half.y && half.x >= half.z ? 0 : (half.y >= half.z ? 1 : 2);
      }
      case SplitAxis::splatter: {
        int best = 0;
        double best_variance = -1;
        for (int k = 0; k < 3; ++k) {
          double sum = 0, sum2 = 0;
          for (const Item& item : items) {
            const double p = projection(item, e.axes.col[k]);
            sum += p, sum2 += p * p;
          }
          const double n = static_cast<double>(items.size());
          const double variance = sum2 / n - (sum / n) * (sum / n);
          if (variance > best_variance) best_variance = variance, best = k;
        }
        return best;
      }
      case SplitAxis::min_sum:
      case SplitAxis::min_max: {
        // The children's sizes: their boxes in the node's frame.
        int best = 0;
        BvSize best_cost{INFINITY, INFINITY};
        std::vector<Item> trial;
        for (int k = 0; k < 3; ++k) {
          trial.assign(items.begin(), items.end());
          const std::uint32_t left = split(trial, e.axes.col[k], e.midpoint(k));
          const BvSize a = vertex_extent(std::span(trial).first(left), e.axes).size();
          const BvSize b = vertex_extent(std::span(trial).subspan(left), e.axes).size();
          const BvSize cost = options_.axis == SplitAxis::min_sum ? a + b : std::max(a, b);
          if (cost < best_cost) best_cost = cost, best = k;
        }
        return best;
      }
    }
    return 0;
  }

  // Splits a node's items in two; returns the size of the first part, in (0, size).
  std::uint32_t split_node(Items items) const {
    if (items.size() == 2) return 1;  // every rule splits two triangles one and one
    const Extent e = extent_of(items, frame_of(items));
    const int k = choose_axis(items, e);
    return split(items, e.axes.col[k], e.midpoint(k));
  }

  const Mesh& mesh_;
  BuildOptions options_;
  std::vector<Item> items_;
};

template <class BV>
Topology top_down_topology(const Mesh& mesh, const BuildOptions& options) {
  return TopDownImpl<BV>(mesh, options).build();
}

template <class BV>
TopDownSplitter<BV>::TopDownSplitter(const Mesh& mesh, const BuildOptions& options)
    : impl_(std::make_unique<TopDownImpl<BV>>(mesh, options)) {}
template <class BV>
TopDownSplitter<BV>::~TopDownSplitter() = default;
template <class BV>
std::uint32_t TopDownSplitter<BV>::split(std::uint32_t first, std::uint32_t count) {
  return impl_->split_range(first, count);
}
template <class BV>
std::uint32_t TopDownSplitter<BV>::face(std::uint32_t slot) const {
  return impl_->face(slot);
}
template <class BV>
std::uint32_t TopDownSplitter<BV>::size() const {
  return impl_->size();
}

#define CC_INSTANTIATE(BV)                                                            \
  template Topology top_down_topology<BV>(const Mesh&, const BuildOptions&);         \
  template class TopDownSplitter<BV>;
CC_FOR_EACH_BOUNDING_VOLUME(CC_INSTANTIATE)
#undef CC_INSTANTIATE

}  // namespace cc::detail
