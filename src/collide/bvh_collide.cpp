#include "collide/bvh_collide.h"

#include <algorithm>
#include <optional>

#include "collide/triangle_triangle.h"

namespace cc {

std::string_view to_string(CollisionMode m) { return m == CollisionMode::first_hit ? "first_hit" : "all_pairs"; }
std::string_view to_string(BvUpdate u) { return u == BvUpdate::approximate ? "approximate" : "exact"; }
std::string_view to_string(Descent d) { return d == Descent::first_model ? "first_model" : "larger"; }

namespace {

Triangle moved(const RigidTransform& t, const Triangle& tri) {
  return {{apply(t, tri.v[0]), apply(t, tri.v[1]), apply(t, tri.v[2])}};
}

// Moving b's points rounds each coordinate by at most transform_error_bound (2^-50 of the
// magnitude plus the translation), once for a triangle's vertex and once for a corner; corners
// carry their own error of 2^-46 of b's magnitude (kdop_corners); a slab along a 3-term
// direction sums three coordinates' errors. That is below 0.9 * 2^-44; 2^-43 is used.
double update_pad(double magnitude, const RigidTransform& t) {
  return 0x1p-43 * (magnitude + max_abs(t.translation)) + fp::subnormal_slack;
}

Obb moved_box(const Bvh<Obb>& b, std::size_t node, const RigidTransform& t, double pad) {
  const Obb& box = b.nodes[node].bv;
  Obb out;
  out.center = apply(t, box.center);
  for (int i = 0; i < 3; ++i) out.axes.col[i] = t.rotation * box.axes.col[i];
  out.half = {box.half.x + pad, box.half.y + pad, box.half.z + pad};
  return out;
}

// Aabb and k-DOPs: re-fitted around moved points, each slab widened by pad times the 1-norm
// of its direction.
// `points` is scratch space (kept by the caller so that a query does not allocate per update).
template <class BV>
BV refitted(const Bvh<BV>& b, std::size_t node, const RigidTransform& t, double pad, BvUpdate update,
            std::vector<Vec3>& points) {
  const std::span<const Vec3> source = update == BvUpdate::approximate ? b.corners.of(node) : b.hull_points.of(node);
  points.clear();
  for (const Vec3& p : source) points.push_back(apply(t, p));
  BV v = BoundingVolume<BV>::fit(points);
  if constexpr (std::is_same_v<BV, Aabb>) {
    v.lo = v.lo - Vec3{pad, pad, pad};
    v.hi = v.hi + Vec3{pad, pad, pad};
  } else {
    const auto dirs = kdop_directions<2 * BV::kSlabs>();
    for (int i = 0; i < BV::kSlabs; ++i) {
      const double w = pad * (std::abs(dirs[i].x) + std::abs(dirs[i].y) + std::abs(dirs[i].z));
      v.lo[i] -= w, v.hi[i] += w;
    }
  }
  return v;
}

template <class BV>
class Traversal {
 public:
  Traversal(const Bvh<BV>& a, const RigidTransform& pose_a, const Bvh<BV>& b, const RigidTransform& pose_b,
            const CollideOptions& options)
      : a_(a), b_(b), t_(relative(pose_a, pose_b)), options_(options) {
    pad_ = update_pad(b.magnitude, t_);
    volumes_.resize(b.nodes.size());
    triangles_.resize(b.triangles.size());
  }

  CollisionResult run() {
    if (a_.nodes.empty() || b_.nodes.empty()) return std::move(result_);
    std::vector<std::pair<std::int32_t, std::int32_t>> stack{{0, 0}};
    while (!stack.empty()) {
      const auto [na, nb] = stack.back();
      stack.pop_back();
      const BvhNode<BV>& x = a_.nodes[na];
      const BvhNode<BV>& y = b_.nodes[nb];
      ++result_.counters.bv_tests;
      if (!BoundingVolume<BV>::overlap(x.bv, volume_of(nb))) continue;
      if (x.leaf() && y.leaf()) {
        if (test_leaves(x, y)) break;
      } else if (descend_b(x, y)) {
        stack.push_back({na, y.right});
        stack.push_back({na, y.left});
      } else {
        stack.push_back({x.right, nb});
        stack.push_back({x.left, nb});
      }
    }
    std::sort(result_.pairs.begin(), result_.pairs.end());
    return std::move(result_);
  }

 private:
  bool descend_b(const BvhNode<BV>& x, const BvhNode<BV>& y) const {
    if (x.leaf()) return true;
    if (y.leaf() || options_.descent == Descent::first_model) return false;
    return BoundingVolume<BV>::size(x.bv) < BoundingVolume<BV>::size(y.bv);
  }

  // b's volume in a's frame, computed once per node and query (a's descent tests the same node
  // of b against many of a's). Moving an OBB is not an update (n_u counts refits only).
  const BV& volume_of(std::int32_t nb) {
    if (!volumes_[nb]) {
      if constexpr (std::is_same_v<BV, Obb>) {
        volumes_[nb] = moved_box(b_, nb, t_, pad_);
      } else {
        volumes_[nb] = refitted(b_, nb, t_, pad_, options_.update, points_);
        ++result_.counters.bv_updates;
      }
    }
    return *volumes_[nb];
  }

  const Triangle& triangle_of(std::uint32_t slot) {
    if (!triangles_[slot]) triangles_[slot] = moved(t_, b_.triangles[slot]);
    return *triangles_[slot];
  }

  // Tests every triangle pair of two leaves; true when the query is answered (first hit).
  bool test_leaves(const BvhNode<BV>& x, const BvhNode<BV>& y) {
    for (std::uint32_t s = x.first; s < x.first + x.count; ++s) {
      for (std::uint32_t r = y.first; r < y.first + y.count; ++r) {
        ++result_.counters.primitive_tests;
        if (!test_triangle_triangle(a_.triangles[s], triangle_of(r))) continue;
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
  double pad_ = 0;
  std::vector<std::optional<BV>> volumes_;
  std::vector<Vec3> points_;  // scratch for refitted()
  std::vector<std::optional<Triangle>> triangles_;
  CollisionResult result_;
};

}  // namespace

template <class BV>
CollisionResult collide(const Bvh<BV>& a, const RigidTransform& pose_a, const Bvh<BV>& b, const RigidTransform& pose_b,
                        const CollideOptions& options) {
  return Traversal<BV>(a, pose_a, b, pose_b, options).run();
}

template <class BV>
BV moved_volume(const Bvh<BV>& b, std::size_t node, const RigidTransform& t, BvUpdate update) {
  if constexpr (std::is_same_v<BV, Obb>) {
    return moved_box(b, node, t, update_pad(b.magnitude, t));
  } else {
    std::vector<Vec3> points;
    return refitted(b, node, t, update_pad(b.magnitude, t), update, points);
  }
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
  template BV moved_volume<BV>(const Bvh<BV>&, std::size_t, const RigidTransform&, BvUpdate);
CC_FOR_EACH_BOUNDING_VOLUME(CC_INSTANTIATE)
#undef CC_INSTANTIATE

}  // namespace cc
