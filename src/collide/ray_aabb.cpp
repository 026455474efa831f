#include "collide/ray_aabb.h"

#include <cfloat>
#include <cmath>
#include <utility>

namespace cc {
namespace {

// A slab parameter (b - o) * (1/d) carries three roundings: at most 3.000001u relative. Widening
// it by 8u (plus the subnormal slack) covers that and the rounding of the widened value itself.
// In multiplicative form, so that a parameter that overflowed to +-inf stays infinite (an
// additive pad would make inf - inf = NaN).
double lower(double t) { return (t > 0 ? t * (1 - 8 * fp::u) : t * (1 + 8 * fp::u)) - fp::subnormal_slack; }
double upper(double t) { return (t > 0 ? t * (1 + 8 * fp::u) : t * (1 - 8 * fp::u)) + fp::subnormal_slack; }

bool in_contract(const Ray& ray, const Aabb& box) {
  return finite(ray.origin) && finite(ray.dir) && finite(box.lo) && finite(box.hi) &&
         ray.tmin < INFINITY && ray.tmax > -INFINITY &&  // also false for NaN
         box.lo.x <= box.hi.x && box.lo.y <= box.hi.y && box.lo.z <= box.hi.z;
}

}  // namespace

RayHit intersect_ray_aabb(const Ray& ray, const Aabb& box) {
  // The direction scaled by a power of two to a largest component in [1, 2), and the parameters
  // with it: then a unit of t is about a unit of space, and a slab parameter that underflows
  // errs by a negligible distance however long or short the direction. Exact; undone on return.
  // (Not when every component is parallel: the parameters then only pass through.)
  const double m = max_abs(ray.dir);
  const int e = (m > 0x1p-1024 && std::isfinite(m)) ? fp::exponent_of(m) : 0;
  const Vec3 dir{fp::scale2(ray.dir.x, -e), fp::scale2(ray.dir.y, -e), fp::scale2(ray.dir.z, -e)};
  const double tmin = fp::scale2(ray.tmin, e), tmax = fp::scale2(ray.tmax, e);
  // tmin and tmax compared as given: scaled, both may underflow to the same value. (Elsewhere an
  // underflowed tmin or tmax errs by less than the padding of the slabs it meets.)
  if (!(ray.tmin <= ray.tmax)) return {};

  // Parallel by contract: 1/d overflows exactly when |d| <= 2^-1024 (0 and -0 included).
  const auto parallel = [&ray](int i) { return std::fabs(ray.dir[i]) <= 0x1p-1024; };
  // The entry and exit parameters of slab i, in the scaled units.
  const auto slab = [&](int i) {
    const double lo = box.lo[i] - ray.origin[i], hi = box.hi[i] - ray.origin[i];
    double near, far;
    if (std::fabs(dir[i]) >= DBL_MIN) {
      const double inv = 1.0 / dir[i];
      near = lo * inv, far = hi * inv;
    } else {
      // A component so much smaller than the largest that, scaled, it is subnormal (rounded,
      // or with a reciprocal that overflows): computed in the caller's units in long double.
      const long double to_scaled = std::ldexp(1.0L, e);
      near = static_cast<double>((static_cast<long double>(box.lo[i]) - ray.origin[i]) / ray.dir[i] * to_scaled);
      far = static_cast<double>((static_cast<long double>(box.hi[i]) - ray.origin[i]) / ray.dir[i] * to_scaled);
    }
    if (ray.dir[i] < 0) std::swap(near, far);
    return std::pair{near, far};
  };

  double enter = -INFINITY, exit = INFINITY;  // over the slabs, as computed
  double enter_low = tmin, exit_high = tmax;  // with tmin and tmax, widened by the rounding bound
  double nears[3] = {0, 0, 0}, fars[3] = {0, 0, 0};  // kept for the hit path
  for (int i = 0; i < 3; ++i) {
    if (parallel(i)) {  // the origin decides, exactly
      if (ray.origin[i] < box.lo[i] || ray.origin[i] > box.hi[i]) return {};
      continue;
    }
    const auto [near, far] = slab(i);
    nears[i] = near, fars[i] = far;
    enter = std::max(enter, near);
    exit = std::min(exit, far);
    enter_low = std::max(enter_low, lower(near));
    exit_high = std::min(exit_high, upper(far));
  }
  if (!(enter_low <= exit_high)) return {};
  if (!in_contract(ray, box)) return {};  // checked on the hit path only
  // The parameters reported in the caller's units: tmin and tmax as given, against the slabs
  // that bind recomputed in those units (in the scaled units a parameter, or tmin and tmax
  // themselves, may have lost bits to underflow). Among slabs that tie, the largest entry and
  // the smallest exit, so the choice does not depend on the order of the axes.
  double t_enter = ray.tmin, t_exit = ray.tmax;
  for (int i = 0; i < 3; ++i) {
    if (parallel(i) || (nears[i] != enter && fars[i] != exit)) continue;
    const double near = nears[i], far = fars[i];
    const double inv = 1.0 / ray.dir[i];
    const double lo = (box.lo[i] - ray.origin[i]) * inv, hi = (box.hi[i] - ray.origin[i]) * inv;
    if (near == enter) t_enter = std::max(t_enter, std::min(lo, hi));
    if (far == exit) t_exit = std::min(t_exit, std::max(lo, hi));
  }
  return {true, t_enter, t_exit};
}

}  // namespace cc
