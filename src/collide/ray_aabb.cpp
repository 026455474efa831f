#include "collide/ray_aabb.h"

#include <utility>

namespace cc {
namespace {

// A slab parameter (b - o) * (1/d) carries three roundings: at most 3.000001u relative. Padding
// by 8u (plus the subnormal slack) covers it and the rounding of the padded value itself.
double pad(double t) { return std::fabs(t) * (8 * fp::u) + fp::subnormal_slack; }

bool in_contract(const Ray& ray, const Aabb& box) {
  return finite(ray.origin) && finite(ray.dir) && finite(box.lo) && finite(box.hi) &&
         ray.tmin < INFINITY && ray.tmax > -INFINITY &&  // also false for NaN
         box.lo.x <= box.hi.x && box.lo.y <= box.hi.y && box.lo.z <= box.hi.z;
}

}  // namespace

RayHit intersect_ray_aabb(const Ray& ray, const Aabb& box) {
  double enter = ray.tmin, exit = ray.tmax;        // as computed
  double enter_low = ray.tmin, exit_high = ray.tmax;  // widened by the rounding bound
  for (int i = 0; i < 3; ++i) {
    const double o = ray.origin[i];
    const double inv = 1.0 / ray.dir[i];
    if (std::isinf(inv)) {  // parallel to this slab: the origin decides, exactly
      if (o < box.lo[i] || o > box.hi[i]) return {};
      continue;
    }
    double t_near = (box.lo[i] - o) * inv;
    double t_far = (box.hi[i] - o) * inv;
    if (inv < 0) std::swap(t_near, t_far);
    enter = std::max(enter, t_near);
    exit = std::min(exit, t_far);
    enter_low = std::max(enter_low, t_near - pad(t_near));
    exit_high = std::min(exit_high, t_far + pad(t_far));
  }
  if (!(enter_low <= exit_high)) return {};
  if (!in_contract(ray, box)) return {};  // checked on the hit path only
  return {true, enter, exit};
}

}  // namespace cc
