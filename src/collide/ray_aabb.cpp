#include "collide/ray_aabb.h"

#include <cfloat>
#include <cmath>
#include <utility>

#include "collide/ray_slab_bound.h"
#include "collide/record_sink.h"

namespace cc {
namespace {

// A slab parameter is moved outward by its rounding bound (bounds::kRaySlab).
double lower(double t) { return bounds::kRaySlab.lower(t); }
double upper(double t) { return bounds::kRaySlab.upper(t); }

bool box_in_contract(const Aabb& box) {
  return finite(box.lo) && finite(box.hi) && box.lo.x <= box.hi.x && box.lo.y <= box.hi.y && box.lo.z <= box.hi.z;
}

// The entry and exit parameters of slab i (not parallel), in the scaled units.
template <class Records>
std::pair<double, double> slab(const PreparedRay& r, const Aabb& box, int i, Records& records) {
  const double lo = box.lo[i] - r.ray.origin[i], hi = box.hi[i] - r.ray.origin[i];
  double near, far;
  if (!((r.subnormal >> i) & 1)) {
    near = lo * r.inv_scaled[i], far = hi * r.inv_scaled[i];
  } else {
    // A component so much smaller than the largest that, scaled, it is subnormal (rounded,
    // or with a reciprocal that overflows): computed in the caller's units in long double.
    const long double to_scaled = std::ldexp(1.0L, r.exponent);
    near = static_cast<double>((static_cast<long double>(box.lo[i]) - r.ray.origin[i]) / r.ray.dir[i] * to_scaled);
    far = static_cast<double>((static_cast<long double>(box.hi[i]) - r.ray.origin[i]) / r.ray.dir[i] * to_scaled);
  }
  records.add(bounds::Quotient{box.lo[i], r.ray.origin[i], r.ray.dir[i], 0, r.exponent, near, bounds::kRaySlab});
  records.add(bounds::Quotient{box.hi[i], r.ray.origin[i], r.ray.dir[i], 0, r.exponent, far, bounds::kRaySlab});
  if (r.negative[i]) std::swap(near, far);
  return {near, far};
}

template <class Records>
RayHit intersect(const PreparedRay& r, const Aabb& box, Records& records);

}  // namespace

// The direction scaled by a power of two to a largest component in [1, 2), and the parameters
// with it: then a unit of t is about a unit of space, and a slab parameter that underflows errs
// by a negligible distance however long or short the direction. Exact; undone on return. (Not
// when every component is parallel: the parameters then only pass through.)
PreparedRay::PreparedRay(const Ray& given) : ray(given) {
  // tmin and tmax compared as given: scaled, both may underflow to the same value. (Elsewhere an
  // underflowed tmin or tmax errs by less than the padding of the slabs it meets.)
  in_contract = ray.tmin <= ray.tmax && finite(ray.origin) && finite(ray.dir) &&  //
                ray.tmin < INFINITY && ray.tmax > -INFINITY;                      // also false for NaN
  const double m = max_abs(ray.dir);
  exponent = (m > 0x1p-1024 && std::isfinite(m)) ? fp::exponent_of(m) : 0;
  tmin = fp::scale2(ray.tmin, exponent), tmax = fp::scale2(ray.tmax, exponent);
  for (int i = 0; i < 3; ++i) {
    negative[i] = ray.dir[i] < 0;
    // Parallel by contract: 1/d overflows exactly when |d| <= 2^-1024 (0 and -0 included).
    if (std::fabs(ray.dir[i]) <= 0x1p-1024) {
      parallel |= 1 << i;
      continue;
    }
    const double d = fp::scale2(ray.dir[i], -exponent);
    if (std::fabs(d) >= DBL_MIN) {
      inv_scaled[i] = 1.0 / d;
    } else {
      subnormal |= 1 << i;
    }
  }
  plain = in_contract && subnormal == 0;
}

RayHit intersect_ray_aabb(const Ray& ray, const Aabb& box) { return intersect_ray_aabb(PreparedRay(ray), box); }

namespace detail {

RayHit intersect_prepared(const PreparedRay& r, const Aabb& box) {
  bounds::NoRecords none;
  return intersect(r, box, none);
}

}  // namespace detail

RayHit intersect_ray_aabb(const Ray& ray, const Aabb& box, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return intersect(PreparedRay(ray), box, into);
}

namespace {

template <class Records>
RayHit intersect(const PreparedRay& r, const Aabb& box, Records& records) {
  if (!r.in_contract) return {};
  double enter = -INFINITY, exit = INFINITY;  // over the slabs, as computed
  double nears[3] = {0, 0, 0}, fars[3] = {0, 0, 0};  // kept for the hit path
  for (int i = 0; i < 3; ++i) {
    if ((r.parallel >> i) & 1) {  // the origin decides, exactly
      if (r.ray.origin[i] < box.lo[i] || r.ray.origin[i] > box.hi[i]) return {};
      continue;
    }
    const auto [near, far] = slab(r, box, i, records);
    nears[i] = near, fars[i] = far;
    enter = std::max(enter, near);
    exit = std::min(exit, far);
  }
  // With tmin and tmax, widened by the rounding bound. lower() and upper() are monotone, so
  // widening the largest entry is widening every entry and taking the largest, bit for bit.
  const double enter_low = std::max(r.tmin, lower(enter)), exit_high = std::min(r.tmax, upper(exit));
  if (!(enter_low <= exit_high)) return {};
  if (!box_in_contract(box)) return {};  // checked on the hit path only
  // The parameters reported in the caller's units: tmin and tmax as given, against the slabs
  // that bind recomputed in those units (in the scaled units a parameter, or tmin and tmax
  // themselves, may have lost bits to underflow). Among slabs that tie, the largest entry and
  // the smallest exit, so the choice does not depend on the order of the axes.
  double t_enter = r.ray.tmin, t_exit = r.ray.tmax;
  for (int i = 0; i < 3; ++i) {
    if (((r.parallel >> i) & 1) || (nears[i] != enter && fars[i] != exit)) continue;
    const double inv = 1.0 / r.ray.dir[i];  // here only: most boxes miss
    const double lo = (box.lo[i] - r.ray.origin[i]) * inv, hi = (box.hi[i] - r.ray.origin[i]) * inv;
    if (nears[i] == enter) t_enter = std::max(t_enter, std::min(lo, hi));
    if (fars[i] == exit) t_exit = std::min(t_exit, std::max(lo, hi));
  }
  return {true, t_enter, t_exit};
}

}  // namespace
}  // namespace cc
