#include "collide/ray_mesh.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "collide/ray_aabb.h"
#include "collide/ray_mesh_bound.h"
#include "collide/ray_triangle_bound.h"
#include "collide/record_sink.h"

namespace cc {
namespace {

// A parameter that carries a few roundings (intersect_ray_aabb's 4 ulps, or a subtraction and
// a division): moved outward by more than that (bounds::kRayVolumeEntry).
double lower(double t) { return bounds::kRayVolumeEntry.lower(t); }
double upper(double t) { return bounds::kRayVolumeEntry.upper(t); }

// The ray with its direction scaled by a power of two to a largest component in [1, 2), and
// tmin and tmax with it, rounded outward: the same points, and the volume tests neither
// overflow nor underflow on a huge or tiny direction. `exponent` undoes it.
struct ScaledRay {
  Ray ray;
  int exponent = 0;

  explicit ScaledRay(const Ray& r) : ray(r) {
    const double m = max_abs(r.dir);
    exponent = m > 0 && std::isfinite(m) ? std::ilogb(m) : 0;
    ray.dir = {std::ldexp(r.dir.x, -exponent), std::ldexp(r.dir.y, -exponent), std::ldexp(r.dir.z, -exponent)};
    ray.tmin = scaled(r.tmin, -INFINITY);
    ray.tmax = scaled(r.tmax, INFINITY);
  }

  // A parameter of the scaled ray in the caller's units, rounded down, at least tmin as given.
  double unscaled_lower(double t, double tmin) const {
    double s = std::ldexp(t, -exponent);
    if (std::isfinite(s) && std::ldexp(s, exponent) != t) s = std::nextafter(s, -INFINITY);
    return std::max(s, tmin);
  }

 private:
  double scaled(double t, double outward) const {
    const double s = std::ldexp(t, exponent);
    return std::isfinite(s) && std::ldexp(s, -exponent) != t ? std::nextafter(s, outward) : s;
  }
};

bool in_contract(const Ray& ray) {
  return finite(ray.origin) && finite(ray.dir) && ray.tmin <= ray.tmax && ray.tmin < INFINITY && ray.tmax > -INFINITY;
}

// The scaled ray against a box grown by pad, the entry in the scaled units (not yet lowered).
RayVolumeEntry enter_box(const Aabb& box, const Ray& ray, double pad) {
  const Vec3 grow{pad, pad, pad};
  const RayHit h = intersect_ray_aabb(ray, Aabb{box.lo - grow, box.hi + grow});
  if (!h.hit) return {};
  return {true, lower(h.t_enter)};
}

RayVolumeEntry enter_scaled(const Aabb& box, const Ray& ray, double pad) { return enter_box(box, ray, pad); }

RayVolumeEntry enter_scaled(const Obb& box, const Ray& ray, double pad) {
  if (!finite(box.center) || !finite(box.half) || !finite(box.axes) || !(box.half.x >= 0 && box.half.y >= 0 && box.half.z >= 0)) {
    return {};
  }
  // In the box's frame the ray is A^T (origin - c) + t A^T dir; the grown box holds it wherever
  // the exact ray is near the volume (see ray_mesh_pad).
  const Ray local{transpose_times(box.axes, ray.origin - box.center), transpose_times(box.axes, ray.dir), ray.tmin,
                  ray.tmax};
  return enter_box(Aabb{-box.half, box.half}, local, pad);
}

// A ball through the cube around it: an entry never later than the ball's. The cube's bounds
// c -+ r round by at most u M, far below the half of pad that covers the volume tests' rounding.
RayVolumeEntry enter_scaled(const Sphere& ball, const Ray& ray, double pad) {
  if (!finite(ball.center) || !fp::finite(ball.radius) || !(ball.radius >= 0)) return {};
  const Vec3 r{ball.radius, ball.radius, ball.radius};
  return enter_box(Aabb{ball.center - r, ball.center + r}, ray, pad);
}

template <int K>
RayVolumeEntry enter_scaled(const Kdop<K>& dop, const Ray& ray, double pad) {
  const auto directions = kdop_directions<K>();
  double enter = ray.tmin, exit = ray.tmax;
  for (int i = 0; i < K / 2; ++i) {
    const Vec3 n{double(directions[i].x), double(directions[i].y), double(directions[i].z)};
    const double grow = pad * norm1(n);
    const double lo = dop.lo[i] - grow, hi = dop.hi[i] + grow;
    if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) return {};  // empty, NaN or unbounded
    const double p = dot(n, ray.origin), q = dot(n, ray.dir);  // products exact, sums rounded
    if (q == 0) {  // parallel: the origin decides
      if (p < lo || p > hi) return {};
      continue;
    }
    double near = (lo - p) / q, far = (hi - p) / q;
    if (q < 0) std::swap(near, far);
    enter = std::max(enter, lower(near));
    exit = std::min(exit, upper(far));
    if (!(enter <= exit) || enter == INFINITY) return {};
  }
  return {true, enter};
}

template <class BV>
bounds::RayMeshPad pad_terms(const Bvh<BV>& bvh, const Ray& ray) {
  return {norm1(ray.origin), bvh.magnitude};
}

// The traversal; each face hit (and each slab of intersect_ray_triangle) is recorded into
// `records`, with the pad.
template <class BV, class Records>
class RayTraversal {
 public:
  RayTraversal(const Bvh<BV>& bvh, const Ray& ray, Records& records)
      : bvh_(bvh), ray_(ray), pad_terms_(pad_terms(bvh, ray)), pad_(pad_terms_.total()), records_(records) {}

  RayMeshHit run(bool stop_at_first) {
    if (bvh_.nodes.empty() || !in_contract(ray_)) return result_;
    const RayVolumeEntry root = test(0);
    if (!root.hit) return result_;
    std::vector<std::pair<std::int32_t, double>> stack{{0, root.t}};
    while (!stack.empty()) {
      const auto [n, entry] = stack.back();
      stack.pop_back();
      if (result_.hit && entry > result_.t) continue;  // certainly beyond the best hit
      const BvhNode<BV>& node = bvh_.nodes[n];
      if (node.leaf()) {
        if (test_leaf(node) && stop_at_first) break;
        continue;
      }
      const RayVolumeEntry left = test(node.left), right = test(node.right);
      // The nearer child on top of the stack (the left one on a tie).
      const bool left_first = !right.hit || (left.hit && left.t <= right.t);
      const std::pair<std::int32_t, double> near{left_first ? node.left : node.right, left_first ? left.t : right.t};
      const std::pair<std::int32_t, double> far{left_first ? node.right : node.left, left_first ? right.t : left.t};
      if ((left_first ? right.hit : left.hit) && reachable(far.second)) stack.push_back(far);
      if ((left_first ? left.hit : right.hit) && reachable(near.second)) stack.push_back(near);
    }
    return result_;
  }

 private:
  bool reachable(double entry) const { return !result_.hit || entry <= result_.t; }

  RayVolumeEntry test(std::int32_t n) {
    ++result_.counters.bv_tests;
    return ray_volume_entry(bvh_.nodes[n].bv, ray_, pad_);
  }

  // Tests the leaf's triangles; true when one was hit.
  bool test_leaf(const BvhNode<BV>& node) {
    bool any = false;
    for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
      ++result_.counters.triangle_tests;
      const Triangle triangle = bvh_.triangle(s);
      const RayTriangleHit h = intersect(triangle);
      if (!h.hit) continue;
      records_.add(bounds::RayMeshFaceHit{ray_, triangle, h.t, pad_terms_});
      any = true;
      const std::uint32_t face = bvh_.order[s];
      if (!result_.hit || h.t < result_.t || (h.t == result_.t && face < result_.face)) {
        result_.hit = true, result_.t = h.t, result_.face = face;
      }
    }
    return any;
  }

  RayTriangleHit intersect(const Triangle& t) {
    if constexpr (std::is_same_v<Records, bounds::RecordsRef>) {
      return intersect_ray_triangle(ray_, t, records_.records);
    } else {
      return intersect_ray_triangle(ray_, t);
    }
  }

  const Bvh<BV>& bvh_;
  Ray ray_;
  bounds::RayMeshPad pad_terms_;
  double pad_;
  Records& records_;
  RayMeshHit result_;
};

}  // namespace

template <class BV>
double ray_mesh_pad(const Bvh<BV>& bvh, const Ray& ray) {
  return pad_terms(bvh, ray).total();
}

template <class BV>
RayVolumeEntry ray_volume_entry(const BV& volume, const Ray& ray, double pad) {
  if (!in_contract(ray) || !(pad >= 0) || !std::isfinite(pad)) return {};
  const ScaledRay scaled(ray);
  const RayVolumeEntry e = enter_scaled(volume, scaled.ray, pad);
  if (!e.hit) return {};
  return {true, scaled.unscaled_lower(e.t, ray.tmin)};
}

template <class BV>
RayMeshHit ray_mesh_closest(const Bvh<BV>& bvh, const Ray& ray) {
  bounds::NoRecords none;
  return RayTraversal<BV, bounds::NoRecords>(bvh, ray, none).run(false);
}

template <class BV>
RayMeshHit ray_mesh_closest(const Bvh<BV>& bvh, const Ray& ray, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return RayTraversal<BV, bounds::RecordsRef>(bvh, ray, into).run(false);
}

template <class BV>
RayMeshHit ray_mesh_any(const Bvh<BV>& bvh, const Ray& ray) {
  bounds::NoRecords none;
  return RayTraversal<BV, bounds::NoRecords>(bvh, ray, none).run(true);
}

RayMeshHit ray_mesh_brute_force(const Mesh& mesh, const Ray& ray) {
  RayMeshHit result;
  for (std::uint32_t f = 0; f < mesh.size(); ++f) {
    ++result.counters.triangle_tests;
    const RayTriangleHit h = intersect_ray_triangle(ray, mesh.triangle(f));
    if (h.hit && (!result.hit || h.t < result.t)) result.hit = true, result.t = h.t, result.face = f;
  }
  return result;
}

#define CC_INSTANTIATE(BV)                                                       \
  template double ray_mesh_pad<BV>(const Bvh<BV>&, const Ray&);                  \
  template RayVolumeEntry ray_volume_entry<BV>(const BV&, const Ray&, double); \
  template RayMeshHit ray_mesh_closest<BV>(const Bvh<BV>&, const Ray&);          \
  template RayMeshHit ray_mesh_closest<BV>(const Bvh<BV>&, const Ray&, bounds::Records&); \
  template RayMeshHit ray_mesh_any<BV>(const Bvh<BV>&, const Ray&);
CC_FOR_EACH_BOUNDING_VOLUME(CC_INSTANTIATE)
#undef CC_INSTANTIATE

}  // namespace cc
