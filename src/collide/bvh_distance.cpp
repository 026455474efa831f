#include "collide/bvh_distance.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "collide/bvh_collide.h"
#include "collide/triangle_distance.h"
#include "collide/volume_gap.h"

namespace cc {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

constexpr double kLargest = 0x1p300;  // the meshes' and translations' magnitude

bool in_domain(const RigidTransform& pose, double magnitude) {
  return finite(pose.rotation) && finite(pose.translation) && max_abs(pose.translation) <= kLargest &&
         magnitude <= kLargest;
}

Triangle placed(const RigidTransform& pose, const Triangle& t) {
  return {{apply(pose, t.v[0]), apply(pose, t.v[1]), apply(pose, t.v[2])}};
}

// The nearest triangle pair so far, and the least lower end of the pairs evaluated.
class Nearest {
 public:
  void offer(const Separation& s, std::uint32_t face_a, std::uint32_t face_b) {
    lowest_ = std::min(lowest_, s.distance - s.distance_error);
    if (!(s.distance < best_.distance)) return;  // on a tie the first stays
    best_ = s;
    faces_ = {face_a, face_b};
  }
  /// An upper bound on the exact distance of the placed triangles (+infinity before the first).
  double upper() const { return best_.distance + best_.distance_error; }
  bool touching() const { return best_.distance == 0; }

  /// The answer for meshes whose placed vertices err by at most e_a and e_b per coordinate.
  /// The exact distance m of the placed triangles lies in [d - err, d + err] above (d the best
  /// distance, err its error) and at least min(lowest, d) below (a pair pruned is farther than
  /// the best pair's upper end), and m >= 0; the placement moves every point of a triangle by at
  /// most sqrt(3) e of its exact place, so the exact meshes' distance by sqrt(3) (e_a + e_b):
  /// 2 (e_a + e_b) is taken, and the sums rounded up.
  MeshSeparation answer(double e_a, double e_b, const DistanceCounters& counters) const {
    MeshSeparation out;
    out.counters = counters;
    if (faces_.first == kNoFace) {
      constexpr double nan = std::numeric_limits<double>::quiet_NaN();
      out.separation = {kInfinity, {nan, nan, nan}, {nan, nan, nan}, 0, 0};
      return out;
    }
    const double d = best_.distance;
    const double below = d - std::max(0.0, lowest_);
    const double error = std::max(best_.distance_error, below);
    out.separation = best_;
    out.separation.distance_error = fp::sum3(error, 2 * e_a, 2 * e_b) * (1 + 4 * fp::u);
    out.separation.point_error = (best_.point_error + 2 * std::max(e_a, e_b)) * (1 + 4 * fp::u);
    out.faces = faces_;
    return out;
  }

 private:
  Separation best_{kInfinity, {}, {}, 0, 0};
  std::pair<std::uint32_t, std::uint32_t> faces_{kNoFace, kNoFace};
  double lowest_ = kInfinity;
};

double size_of(const Obb& box) { return norm1(box.half); }
double size_of(const Sphere& ball) { return ball.radius; }

template <class BV>
class DistanceWalk {
 public:
  DistanceWalk(const Bvh<BV>& a, const RigidTransform& pose_a, const Bvh<BV>& b, const RigidTransform& pose_b)
      : a_(a), b_(b), pose_a_(pose_a), pose_b_(pose_b) {}

  MeshSeparation run() {
    const double e_a = transform_error_bound(pose_a_, a_.magnitude), e_b = transform_error_bound(pose_b_, b_.magnitude);
    if (a_.nodes.empty() || b_.nodes.empty()) return nearest_.answer(e_a, e_b, counters_);
    push(0, 0, moved(a_, 0, pose_a_), moved(b_, 0, pose_b_));
    while (!stack_.empty() && !nearest_.touching()) {
      const Visit v = stack_.back();
      stack_.pop_back();
      if (v.lower > nearest_.upper()) continue;  // pruned since it was pushed
      const auto& na = a_.nodes[v.a];
      const auto& nb = b_.nodes[v.b];
      if (na.leaf() && nb.leaf()) {
        leaves(na, nb);
      } else if (nb.leaf() || (!na.leaf() && size_of(v.va) >= size_of(v.vb))) {
        children(v, true);
      } else {
        children(v, false);
      }
    }
    return nearest_.answer(e_a, e_b, counters_);
  }

 private:
  struct Visit {
    std::uint32_t a, b;
    BV va, vb;
    double lower;
  };

  static BV moved(const Bvh<BV>& tree, std::size_t node, const RigidTransform& pose) {
    return moved_volume(tree, node, pose, BvUpdate::approximate);  // moved whole: no refit
  }

  void push(std::uint32_t a, std::uint32_t b, const BV& va, const BV& vb) {
    ++counters_.bv_tests;
    const double lower = volume_gap(va, vb);
    if (lower > nearest_.upper()) return;
    stack_.push_back({a, b, va, vb, lower});
  }

  // Splits a's node (or b's), pushing the farther child pair first so that the nearer is
  // visited first.
  void children(const Visit& v, bool split_a) {
    const Bvh<BV>& tree = split_a ? a_ : b_;
    const auto& node = tree.nodes[split_a ? v.a : v.b];
    const RigidTransform& pose = split_a ? pose_a_ : pose_b_;
    const auto left = static_cast<std::uint32_t>(node.left), right = static_cast<std::uint32_t>(node.right);
    const BV l = moved(tree, left, pose), r = moved(tree, right, pose);
    const std::size_t before = stack_.size();
    if (split_a) {
      push(left, v.b, l, v.vb);
      push(right, v.b, r, v.vb);
    } else {
      push(v.a, left, v.va, l);
      push(v.a, right, v.va, r);
    }
    if (stack_.size() == before + 2 && stack_[before].lower < stack_[before + 1].lower) {
      std::swap(stack_[before], stack_[before + 1]);
    }
  }

  void leaves(const BvhNode<BV>& na, const BvhNode<BV>& nb) {
    for (std::uint32_t i = na.first; i < na.first + na.count; ++i) {
      const Triangle ta = placed(pose_a_, a_.triangle(i));
      for (std::uint32_t j = nb.first; j < nb.first + nb.count; ++j) {
        ++counters_.primitive_tests;
        nearest_.offer(distance_triangle_triangle(ta, placed(pose_b_, b_.triangle(j))), a_.order[i], b_.order[j]);
      }
    }
  }

  const Bvh<BV>& a_;
  const Bvh<BV>& b_;
  const RigidTransform& pose_a_;
  const RigidTransform& pose_b_;
  Nearest nearest_;
  DistanceCounters counters_;
  std::vector<Visit> stack_;
};

double magnitude_of(const Mesh& mesh) {
  double m = 0;
  for (const Vec3& v : mesh.vertices) m = std::max(m, norm1(v));
  return m;
}

}  // namespace

template <class BV>
MeshSeparation distance(const Bvh<BV>& a, const RigidTransform& pose_a, const Bvh<BV>& b, const RigidTransform& pose_b) {
  if (!in_domain(pose_a, a.magnitude) || !in_domain(pose_b, b.magnitude)) {
    return {Separation::outside_the_domain(), {kNoFace, kNoFace}, {}};
  }
  return DistanceWalk<BV>(a, pose_a, b, pose_b).run();
}

MeshSeparation distance_brute_force(const Mesh& a, const RigidTransform& pose_a, const Mesh& b,
                                    const RigidTransform& pose_b) {
  const double magnitude_a = magnitude_of(a), magnitude_b = magnitude_of(b);
  if (!in_domain(pose_a, magnitude_a) || !in_domain(pose_b, magnitude_b)) {
    return {Separation::outside_the_domain(), {kNoFace, kNoFace}, {}};
  }
  std::vector<Triangle> placed_b;
  for (std::size_t j = 0; j < b.size(); ++j) placed_b.push_back(placed(pose_b, b.triangle(j)));
  Nearest nearest;
  DistanceCounters counters;
  for (std::uint32_t i = 0; i < a.size(); ++i) {
    const Triangle ta = placed(pose_a, a.triangle(i));
    for (std::uint32_t j = 0; j < b.size(); ++j) {
      ++counters.primitive_tests;
      nearest.offer(distance_triangle_triangle(ta, placed_b[j]), i, j);
    }
  }
  return nearest.answer(transform_error_bound(pose_a, magnitude_a), transform_error_bound(pose_b, magnitude_b), counters);
}

template MeshSeparation distance<Obb>(const Bvh<Obb>&, const RigidTransform&, const Bvh<Obb>&, const RigidTransform&);
template MeshSeparation distance<Sphere>(const Bvh<Sphere>&, const RigidTransform&, const Bvh<Sphere>&,
                                         const RigidTransform&);

}  // namespace cc
