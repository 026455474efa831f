#include "collide/bvh_collide.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "collide/bvh_lazy.h"
#include "collide/kdop_support.h"
#include "collide/triangle_triangle.h"

namespace cc {

std::string_view to_string(CollisionMode m) { return m == CollisionMode::first_hit ? "first_hit" : "all_pairs"; }
std::string_view to_string(BvUpdate u) {
  switch (u) {
    case BvUpdate::approximate: return "approximate";
    case BvUpdate::exact: return "exact";
    case BvUpdate::hill_climbing: return "hill_climbing";
  }
  return "?";
}
std::string_view to_string(Descent d) { return d == Descent::first_model ? "first_model" : "larger"; }

namespace {

Triangle moved(const RigidTransform& t, const Triangle& tri) {
  return {{apply(t, tri.v[0]), apply(t, tri.v[1]), apply(t, tri.v[2])}};
}

// A triangle of b moved into a's frame, and its box.
struct MovedTriangle {
  Triangle triangle;
  Aabb box;
};

// The smallest box that holds the triangle (exactly: its vertices' own coordinates).
Aabb box_of(const Triangle& t) {
  Aabb b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = std::min(std::min(t.v[0][k], t.v[1][k]), t.v[2][k]);
    b.hi[k] = std::max(std::max(t.v[0][k], t.v[1][k]), t.v[2][k]);
  }
  return b;
}

// Moving b's vertices rounds each coordinate by at most transform_error_bound (2^-50 of b's
// magnitude plus the translation); the approximate update's bounds carry below 2^-45 of the
// same, times the slab direction's 1-norm (see VolumeMover); a slab along a 3-term direction
// sums three coordinates' errors. 2^-43 is used.
double update_pad(double magnitude, const RigidTransform& t) {
  return 0x1p-43 * (magnitude + max_abs(t.translation)) + fp::subnormal_slack;
}

Obb moved_box(const Obb& box, const RigidTransform& t, double pad) {
  Obb out;
  out.center = apply(t, box.center);
  for (int i = 0; i < 3; ++i) out.axes.col[i] = t.rotation * box.axes.col[i];
  out.half = {box.half.x + pad, box.half.y + pad, box.half.z + pad};
  return out;
}

// A bound on |R x| / |x| for the rotation R of t: |R x|^2 = x^T R^T R x <= (1 + g) |x|^2 with g the
// largest row sum of |R^T R - I| (Gershgorin), and sqrt(1 + g) <= 1 + g / 2. Each entry of R^T R
// sums three products of entries at most 1 + 2^-48 in magnitude (RigidTransform), so it rounds
// by less than 2^-50 and a row sum by less than 2^-47; 1 + g / 2 rounds by less than 2^-52.
double stretch_bound(const RigidTransform& t) {
  const Mat3& r = t.rotation;
  double g = 0;
  for (int i = 0; i < 3; ++i) {
    double row = 0;
    for (int j = 0; j < 3; ++j) {
      const double entry = r.col[i].x * r.col[j].x + r.col[i].y * r.col[j].y + r.col[i].z * r.col[j].z;
      row += std::fabs(entry - (i == j ? 1.0 : 0.0));
    }
    g = std::max(g, row);
  }
  return 1 + 0.5 * (g + 0x1p-47) + 0x1p-51;
}

// A ball moved by t: its centre by apply(), its radius stretched by stretch_bound(t) and padded.
// The ball holds each vertex v of the node (|v - c| <= r), and the leaf test sees apply(t, v),
// within sqrt(3) transform_error_bound of R v + T, as the centre is of R c + T: so apply(t, v)
// lies within stretch r + 2 sqrt(3) 2^-50 (M + |T|) of apply(t, c), below the radius plus pad.
Sphere moved_ball(const Sphere& ball, const RigidTransform& t, double stretch, double pad) {
  return {apply(t, ball.center), std::nextafter(ball.radius * stretch, INFINITY) + pad};
}

// Whether b's volumes are moved by t as they are (an Obb, a ball: no update) rather than
// re-fitted in a's frame (an Aabb, a k-DOP).
template <class BV>
inline constexpr bool kMovedWhole = std::is_same_v<BV, Obb> || std::is_same_v<BV, Sphere>;

// Brings volumes of b into a's frame for one relative transform t (b to a), each slab widened
// by pad times the 1-norm of its direction.
//  - Obb: moved by t.
//  - Sphere: its centre moved by t, its radius stretched by t's rotation (moved_ball).
//  - approximate: slab i of the moved volume, along n_i, is [-h(-m_i), h(m_i)] + n_i . T with
//    m_i = R^T n_i, where h is the support of b's volume bounded through three of its slabs
//    (kdop_cone, support_bound; for a box, exactly the support: the box around its moved
//    corners). Errors, each times |n_i|_1 at most: m_i's rounding 2u M (M = b's magnitude,
//    which bounds |x|_1 over every volume), the cone's residual 2^-46 M, support_bound's 27u M
//    (the coefficients sum to at most 9 |m_i|_max), n_i . T's 2u |T| and the last sum's
//    u (9 M + |T|), the leaf test's moving of a vertex 2u (M + |T|): below 2^-45 (M + |T|).
//  - exact: the moved hull points of the node (BuildOptions::hull_points), or all its vertices,
//    re-fitted (fit_kdop rounds outward), then padded.
template <class BV>
class VolumeMover {
 public:
  VolumeMover(const Bvh<BV>& b, const RigidTransform& t, BvUpdate update)
      : b_(b), t_(t), update_(update), pad_(update_pad(b.magnitude, t)) {
    if constexpr (kMovedWhole<BV>) {
      if constexpr (std::is_same_v<BV, Sphere>) stretch_ = stretch_bound(t);
    } else {
      if (update_ == BvUpdate::exact) return;
      const auto dirs = kdop_directions<2 * kSlabs>();
      for (int i = 0; i < kSlabs; ++i) {
        const Vec3 n{double(dirs[i].x), double(dirs[i].y), double(dirs[i].z)};
        const Vec3 m = transpose_times(t.rotation, n);
        if (update_ == BvUpdate::hill_climbing) {
          climb_[i] = m;
          // Twice the rounding of a walk's value m . p (three products and two sums, |p|_1 <= M),
          // and twice a bound on |slab value - (m . p + n . T)| over the hull points, in exact
          // arithmetic: the moved point's rounding and the fit's outward rounding, each a few
          // units of roundoff of (M + |T|_1) |n|_1, and m's rounding times M; 2^-44 is more than
          // eight times their sum.
          walk_error_[i] = 2 * (4 * fp::u * norm1(m) * b.magnitude) + fp::subnormal_slack;
          value_error_[i] = 2 * (0x1p-44 * (b.magnitude + 3 * max_abs(t.translation)) * norm1(n)) + fp::subnormal_slack;
          continue;
        }
        upper_[i] = kdop_cone<2 * kSlabs>(m);
        lower_[i] = upper_[i];  // -m: the opposite normals, the same coefficients
        for (int& h : lower_[i].normal) h = h < kSlabs ? h + kSlabs : h - kSlabs;
        offset_[i] = dot(n, t.translation);
        width_[i] = pad_ * norm1(n);
      }
    }
  }

  // Points the updates evaluated so far (CollisionCounters::update_points), and the updates hill
  // climbing found (CollisionCounters::climbed).
  std::uint64_t points_evaluated() const { return evaluated_; }
  std::uint64_t climbed() const { return climbed_; }

  BV operator()(std::size_t node) const {
    const BV& v = b_.nodes[node].bv;
    if constexpr (std::is_same_v<BV, Obb>) {
      return moved_box(v, t_, pad_);
    } else if constexpr (std::is_same_v<BV, Sphere>) {
      return moved_ball(v, t_, stretch_, pad_);
    } else if constexpr (std::is_same_v<BV, Aabb>) {
      Kdop<6> box;
      box.lo = {v.lo.x, v.lo.y, v.lo.z}, box.hi = {v.hi.x, v.hi.y, v.hi.z};
      const Kdop<6> m = move(box, node);
      return {{m.lo[0], m.lo[1], m.lo[2]}, {m.hi[0], m.hi[1], m.hi[2]}};
    } else {
      return move(v, node);
    }
  }

 private:
  static constexpr int kSlabs = kSlabDirections<BV>;
  using Dop = Kdop<2 * kSlabs>;

  Dop move(const Dop& dop, std::size_t node) const {
    Dop out;
    if (update_ == BvUpdate::approximate) {
      for (int i = 0; i < kSlabs; ++i) {
        out.lo[i] = (-support_bound(dop, lower_[i]) + offset_[i]) - width_[i];
        out.hi[i] = (support_bound(dop, upper_[i]) + offset_[i]) + width_[i];
      }
      return out;
    }
    std::vector<Vec3> points;
    const auto add = [&](const Vec3& p) { points.push_back(apply(t_, p)); };
    if (update_ == BvUpdate::hill_climbing && !b_.hull_graphs.walkable.empty() && b_.hull_graphs.walkable[node] &&
        climb(node, points)) {
      ++climbed_;  // every slab's highest and lowest hull points, moved: nothing more to add
    } else if (!b_.hull_points.range.empty()) {
      for (const Vec3& p : b_.hull_points.of(node)) add(p);
      evaluated_ += points.size();
    } else {
      const BvhNode<BV>& n = b_.nodes[node];
      for (std::uint32_t s = n.first; s < n.first + n.count; ++s) {
        for (std::uint32_t v : b_.faces[s]) add(b_.vertices[v]);
      }
      evaluated_ += points.size();
    }
    out = fit_kdop<2 * kSlabs>(points);
    const auto dirs = kdop_directions<2 * kSlabs>();
    for (int i = 0; i < kSlabs; ++i) {
      const double w = pad_ * (std::abs(dirs[i].x) + std::abs(dirs[i].y) + std::abs(dirs[i].z));
      out.lo[i] -= w, out.hi[i] += w;
    }
    return out;
  }

  // The hill-climbing update of a node: per slab direction and side, a walk up the node's hull
  // graph by m . p to a point v no neighbour of which is higher, then the plateau around v: the
  // points connected to it whose values are within 2 `margin` below v's. Every point next to the
  // plateau is lower than that, so (`margin` exceeding the errors) exactly lower than v: the
  // climbing paths the hull graph has from v stay on the plateau up to the maximum, and a
  // climbing path from any point off the plateau enters it through a point next to it, so is
  // lower still, and so is its slab value than v's. When every walk's plateau is whole (at most
  // kMostOnAPlateau points): the plateaus' points moved (into `points`), and true.
  bool climb(std::size_t node, std::vector<Vec3>& points) const {
    constexpr std::size_t kMostOnAPlateau = 64;
    const NodeGraphs& g = b_.hull_graphs;
    const std::uint32_t first = b_.hull_points.range[node].first, count = b_.hull_points.range[node].second;
    const std::span<const Vec3> hull = b_.hull_points.of(node);
    ends_.clear();
    for (int w = 0; w < 2 * kSlabs; ++w) {
      const int i = w / 2;
      const Vec3 m = w % 2 == 0 ? climb_[i] : -climb_[i];
      const double margin = walk_error_[i] + value_error_[i];
      const auto value = [&](std::uint32_t p) {
        ++evaluated_;
        return m.x * hull[p].x + m.y * hull[p].y + m.z * hull[p].z;
      };
      std::atomic_ref<std::uint32_t> start(g.start[node * 2 * kSlabs + static_cast<std::size_t>(w)]);
      std::uint32_t v = start.load(std::memory_order_relaxed);
      if (v >= count) v = 0;
      double at = value(v);
      for (;;) {  // steepest ascent; `around_` keeps the values of v's neighbours
        std::uint32_t best = v;
        around_.clear();
        for (std::uint32_t u : g.neighbours_of(first + v)) {
          const double x = value(u);
          around_.emplace_back(u, x);
          if (x > at) best = u, at = x;
        }
        if (best == v) break;
        v = best;
      }
      start.store(v, std::memory_order_relaxed);
      if (std::isnan(at)) return false;  // out of contract: no certificate
      plateau_.assign(1, {v, at});
      for (std::size_t k = 0; k < plateau_.size(); ++k) {
        const auto neighbours = g.neighbours_of(first + plateau_[k].first);
        for (std::size_t j = 0; j < neighbours.size(); ++j) {
          const std::uint32_t u = neighbours[j];
          if (std::any_of(plateau_.begin(), plateau_.end(), [&](const auto& q) { return q.first == u; })) continue;
          const double x = k == 0 ? around_[j].second : value(u);
          if (x >= at - 2 * margin) {
            if (plateau_.size() == kMostOnAPlateau) return false;
            plateau_.emplace_back(u, x);
          }
        }
      }
      for (const auto& q : plateau_) ends_.push_back(q.first);
    }
    std::sort(ends_.begin(), ends_.end());
    points.clear();
    for (std::size_t k = 0; k < ends_.size(); ++k) {
      if (k == 0 || ends_[k] != ends_[k - 1]) points.push_back(apply(t_, hull[ends_[k]]));
    }
    return true;
  }

  const Bvh<BV>& b_;
  RigidTransform t_;
  BvUpdate update_;
  double pad_;
  std::array<Vec3, kSlabs> climb_{};  // hill climbing: m_i = R^T n_i
  std::array<double, kSlabs> walk_error_{}, value_error_{};
  mutable std::uint64_t evaluated_ = 0, climbed_ = 0;
  mutable std::vector<std::pair<std::uint32_t, double>> plateau_, around_;  // hill climbing's scratch
  mutable std::vector<std::uint32_t> ends_;
  double stretch_ = 1;  // spheres: stretch_bound(t_)
  std::array<KdopCone<2 * kSlabs>, kSlabs> upper_, lower_;
  std::array<double, kSlabs> offset_{}, width_{};
};

// The walk over two hierarchies, eager ones (lazy_a and lazy_b null) or lazy ones, whose nodes
// are split when the walk first descends into them (their node arrays then grow: nodes are read
// by index, not kept by reference, across a split).
template <class BV>
class Traversal {
 public:
  Traversal(const Bvh<BV>& a, const RigidTransform& pose_a, const Bvh<BV>& b, const RigidTransform& pose_b,
            const CollideOptions& options, LazyBvh<BV>* lazy_a = nullptr, LazyBvh<BV>* lazy_b = nullptr)
      : a_(a), b_(b), t_(relative(pose_a, pose_b)), options_(options), mover_(b, t_, options.update),
        lazy_a_(lazy_a), lazy_b_(lazy_b), volume_slot_(b.nodes.size(), -1), triangle_slot_(b.faces.size(), -1) {
    volumes_.reserve(b.nodes.size());
  }

  CollisionResult run() {
    if (a_.nodes.empty() || b_.nodes.empty()) return std::move(result_);
    // Pairs of nodes still to test, as a stack that grows by doubling (push_back is not inlined,
    // nor is this lambda unless asked).
    std::vector<std::pair<std::int32_t, std::int32_t>> stack(64);
    std::size_t size = 0;
    const auto push = [&](std::int32_t na, std::int32_t nb) __attribute__((always_inline)) {
      if (size == stack.size()) stack.resize(2 * size);
      stack[size++] = {na, nb};
    };
    for (push(0, 0); size > 0;) {
      const auto [na, nb] = stack[--size];
      ++result_.counters.bv_tests;
      if (!BoundingVolume<BV>::overlap(a_.nodes[na].bv, volume_of(nb))) continue;
      const BvhNode<BV>& x = a_.nodes[na];
      const BvhNode<BV>& y = b_.nodes[nb];
      if (x.leaf() && y.leaf()) {
        if (test_leaves(x, y)) break;
      } else if (descend_b(x, y)) {
        if (lazy_b_ != nullptr) lazy_b_->split(nb);  // (x and y are not read after this)
        push(na, b_.nodes[nb].right);
        push(na, b_.nodes[nb].left);
      } else {
        if (lazy_a_ != nullptr) lazy_a_->split(na);
        push(a_.nodes[na].right, nb);
        push(a_.nodes[na].left, nb);
      }
    }
    std::sort(result_.pairs.begin(), result_.pairs.end());
    result_.counters.update_points = mover_.points_evaluated();
    result_.counters.climbed = mover_.climbed();
    return std::move(result_);
  }

 private:
  bool descend_b(const BvhNode<BV>& x, const BvhNode<BV>& y) const {
    if (x.leaf()) return true;
    if (y.leaf() || options_.descent == Descent::first_model) return false;
    return BoundingVolume<BV>::size(x.bv) < BoundingVolume<BV>::size(y.bv);
  }

  // b's volume in a's frame, computed once per node and query (a's descent tests the same node
  // of b against many of a's). Moving an OBB or a ball is not an update (n_u counts refits only).
  const BV& volume_of(std::int32_t nb) {
    if (static_cast<std::size_t>(nb) >= volume_slot_.size()) volume_slot_.resize(b_.nodes.size(), -1);  // lazy b grew
    std::int32_t& slot = volume_slot_[nb];
    if (slot < 0) {
      slot = static_cast<std::int32_t>(volumes_.size());
      volumes_.push_back(mover_(static_cast<std::size_t>(nb)));
      if constexpr (!kMovedWhole<BV>) ++result_.counters.bv_updates;
    }
    return volumes_[slot];
  }

  // b's triangle in slot s moved into a's frame (as the leaf test sees it), and its box.
  const MovedTriangle& triangle_of(std::uint32_t s) {
    std::int32_t& slot = triangle_slot_[s];
    if (slot < 0) {
      slot = static_cast<std::int32_t>(triangles_.size());
      const Triangle t = moved(t_, b_.triangle(s));
      triangles_.push_back({t, box_of(t)});
    }
    return triangles_[slot];
  }

  // Tests every triangle pair of two leaves; true when the query is answered (first hit). Pairs
  // whose boxes are apart are not tested: their triangles are apart.
  bool test_leaves(const BvhNode<BV>& x, const BvhNode<BV>& y) {
    for (std::uint32_t s = x.first; s < x.first + x.count; ++s) {
      const Triangle ta = a_.triangle(s);
      const Aabb box_a = box_of(ta);
      for (std::uint32_t r = y.first; r < y.first + y.count; ++r) {
        const MovedTriangle& tb = triangle_of(r);
        if (!test_aabb_aabb(box_a, tb.box)) continue;
        ++result_.counters.primitive_tests;
        if (!test_triangle_triangle(ta, tb.triangle)) continue;
        result_.pairs.emplace_back(a_.order[s], b_.order[r]);
        if (options_.mode == CollisionMode::first_hit) return true;
      }
    }
    return false;
  }

  const Bvh<BV>& a_;
  const Bvh<BV>& b_;
  RigidTransform t_;
  CollideOptions options_;
  VolumeMover<BV> mover_;
  LazyBvh<BV>* lazy_a_;
  LazyBvh<BV>* lazy_b_;
  std::vector<std::int32_t> volume_slot_, triangle_slot_;  // index into volumes_, triangles_; -1 until moved
  std::vector<BV> volumes_;
  std::vector<MovedTriangle> triangles_;
  CollisionResult result_;
};

}  // namespace

template <class BV>
CollisionResult collide(const Bvh<BV>& a, const RigidTransform& pose_a, const Bvh<BV>& b, const RigidTransform& pose_b,
                        const CollideOptions& options) {
  return Traversal<BV>(a, pose_a, b, pose_b, options).run();
}

template <class BV>
CollisionResult collide(LazyBvh<BV>& a, const RigidTransform& pose_a, LazyBvh<BV>& b, const RigidTransform& pose_b,
                        const CollideOptions& options) {
  return Traversal<BV>(a.tree(), pose_a, b.tree(), pose_b, options, &a, &b).run();
}

template <class BV>
BV moved_volume(const Bvh<BV>& b, std::size_t node, const RigidTransform& t, BvUpdate update) {
  return VolumeMover<BV>(b, t, update)(node);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> collide_brute_force(const Mesh& a, const RigidTransform& pose_a,
                                                                         const Mesh& b, const RigidTransform& pose_b) {
  const RigidTransform t = relative(pose_a, pose_b);
  std::vector<Triangle> moved_b;
  for (std::size_t j = 0; j < b.size(); ++j) moved_b.push_back(moved(t, b.triangle(j)));
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t i = 0; i < a.size(); ++i) {
    const Triangle ta = a.triangle(i);
    for (std::uint32_t j = 0; j < b.size(); ++j) {
      if (test_triangle_triangle(ta, moved_b[j])) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

#define CC_INSTANTIATE(BV)                                                                                \
  template CollisionResult collide<BV>(const Bvh<BV>&, const RigidTransform&, const Bvh<BV>&, const RigidTransform&, \
                                       const CollideOptions&);                                          \
  template CollisionResult collide<BV>(LazyBvh<BV>&, const RigidTransform&, LazyBvh<BV>&, const RigidTransform&, \
                                       const CollideOptions&);                                          \
  template BV moved_volume<BV>(const Bvh<BV>&, std::size_t, const RigidTransform&, BvUpdate);
CC_FOR_EACH_BOUNDING_VOLUME(CC_INSTANTIATE)
#undef CC_INSTANTIATE

}  // namespace cc
