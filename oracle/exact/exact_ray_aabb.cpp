// ray_aabb in exact arithmetic.
//
// Answer: the ray meets the box iff max(tmin, entry parameters) <= min(tmax, exit parameters),
// with a slab whose direction component is 0 replaced by the test "origin inside the slab".
// The library's contract makes a component whose reciprocal overflows (a tiny subnormal) such a
// parallel component too; the reference applies that definition before computing exactly.
// Margin: the smallest uniform growth delta of the box (a shrinking when negative) after which
// the ray touches it. Every condition of the answer is linear in delta -- entry_i(delta) =
// (near_i - o_i - delta)/d_i, exit likewise -- so delta* is the largest of the deltas that each
// condition needs, and margin = -delta* / scale.
#include <cmath>
#include <optional>

#include "oracle/exact/domain.h"
#include "oracle/exact/judges.h"
#include "oracle/exact/rational.h"

namespace cc::exact {
namespace {

struct Slab {
  Rational near_t, far_t;  // entry and exit parameters
  Rational speed;          // |d_i|
};

}  // namespace

ExactVerdict judge(const harness::RayAabbInput& in) {
  const Ray& ray = in.ray;
  const Aabb& box = in.box;
  const Vec3 &o = ray.origin, &lo = box.lo, &hi = box.hi;
  Vec3 d = ray.dir;
  if (has_nan({o.x, o.y, o.z, d.x, d.y, d.z, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, ray.tmin, ray.tmax})) {
    return documented(false, "NaN input");
  }
  if (!all_finite({o.x, o.y, o.z, d.x, d.y, d.z, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z})) {
    return documented(false, "infinite coordinate");
  }
  if (ray.tmin == INFINITY || ray.tmax == -INFINITY) return documented(false, "tmin = +inf or tmax = -inf");
  if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) return documented(false, "inverted box");

  std::string flushed;
  for (int i = 0; i < 3; ++i) {
    if (d[i] != 0 && std::isinf(1.0 / d[i])) {  // documented: treated as parallel
      flushed += std::string(flushed.empty() ? "" : ", ") + "dir." + "xyz"[i];
      d[i] = 0;
    }
  }
  const double magnitude = max_magnitude({o.x, o.y, o.z, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
  const bool parallel_by_contract = !flushed.empty();

  const std::optional<Rational> tmin =
      ray.tmin == -INFINITY ? std::nullopt : std::optional<Rational>(rational(ray.tmin));
  const std::optional<Rational> tmax =
      ray.tmax == INFINITY ? std::nullopt : std::optional<Rational>(rational(ray.tmax));

  std::optional<Rational> enter = tmin, exit = tmax;  // nullopt: -inf and +inf
  std::optional<Rational> delta;                      // the growth each condition needs, maximised
  const auto need = [&delta](const Rational& v) {
    if (!delta || v > *delta) delta = v;
  };
  bool outside_parallel_slab = false;
  std::vector<Slab> slabs;
  const Rational limit = rational(0x1p1000);
  for (int i = 0; i < 3; ++i) {
    const Rational oi = rational(o[i]), li = rational(lo[i]), hi_i = rational(hi[i]);
    if (d[i] == 0) {
      need(li - oi);
      need(oi - hi_i);
      if (oi < li || oi > hi_i) outside_parallel_slab = true;
      continue;
    }
    const Rational di = rational(d[i]);
    Rational t0 = (li - oi) / di, t1 = (hi_i - oi) / di;
    if (abs(t0) > limit || abs(t1) > limit) {
      return unspecified("slab parameter beyond 2^1000 on axis " + std::string(1, "xyz"[i]));
    }
    if (sgn(di) < 0) std::swap(t0, t1);
    if (!enter || t0 > *enter) enter = t0;
    if (!exit || t1 < *exit) exit = t1;
    slabs.push_back({t0, t1, abs(di)});
  }
  if (auto why = scale_outside(magnitude, -900, 1000)) return unspecified(*why);

  for (const Slab& a : slabs) {
    for (const Slab& b : slabs) need((a.near_t - b.far_t) * a.speed * b.speed / (a.speed + b.speed));
    if (tmax) need((a.near_t - *tmax) * a.speed);
    if (tmin) need((*tmin - a.far_t) * a.speed);
  }
  const bool empty_range = tmin && tmax && *tmin > *tmax;
  const bool hit = !outside_parallel_slab && !empty_range && (!enter || !exit || *enter <= *exit);

  ExactVerdict v;
  v.answer.hit = hit;
  if (hit) {
    v.answer.params = {enter ? to_double(*enter) : -INFINITY, exit ? to_double(*exit) : INFINITY};
  }
  if (empty_range) {
    v.margin = -INFINITY;
  } else {
    v.margin = -to_double(*delta) / scale_of(magnitude);
    if ((sgn(*delta) <= 0) != hit) {
      v.decided = false;
      v.note = "internal inconsistency: margin and answer disagree";
    }
  }
  if (parallel_by_contract) {  // in the domain: the contract defines such a ray as parallel
    v.note = "direction component(s) " + flushed + " have an overflowing reciprocal: parallel by contract";
  }
  return v;
}

}  // namespace cc::exact
