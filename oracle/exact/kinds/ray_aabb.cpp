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
#include "oracle/exact/kinds/ray_aabb.h"

#include <cmath>

#include "oracle/exact/domain.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {
namespace {

const char* const kAxis[] = {"x", "y", "z"};

}  // namespace

RayAnalysis analyse_ray(const harness::RayAabbInput& in) {
  const Ray& ray = in.ray;
  RayAnalysis r;
  if (ray.tmin != -INFINITY) r.tmin = rational(ray.tmin);
  if (ray.tmax != INFINITY) r.tmax = rational(ray.tmax);
  r.enter = r.tmin;
  r.exit = r.tmax;
  bool first = true;
  const auto need = [&](const Rational& v, const std::string& why) {
    if (first || v > r.delta) r.delta = v, r.binding = why;
    first = false;
  };
  bool outside_parallel_slab = false;
  for (int i = 0; i < 3; ++i) {
    RaySlab s{i, false, true, 0, 0, 0};
    const double d = ray.dir[i];
    const bool by_contract = d != 0 && std::isinf(1.0 / d);
    if (by_contract) r.flushed += std::string(r.flushed.empty() ? "" : ", ") + "dir." + kAxis[i];
    const Rational o = rational(ray.origin[i]), lo = rational(in.box.lo[i]), hi = rational(in.box.hi[i]);
    if (d == 0 || by_contract) {
      s.parallel = true;
      s.origin_inside = !(o < lo || o > hi);
      outside_parallel_slab |= !s.origin_inside;
      need(lo - o, std::string("parallel to the ") + kAxis[i] + " slab, origin below it");
      need(o - hi, std::string("parallel to the ") + kAxis[i] + " slab, origin above it");
    } else {
      const Rational di = rational(d);
      s.near_t = (lo - o) / di;
      s.far_t = (hi - o) / di;
      if (sgn(di) < 0) std::swap(s.near_t, s.far_t);
      s.speed = abs(di);
      if (!r.enter || s.near_t > *r.enter) r.enter = s.near_t;
      if (!r.exit || s.far_t < *r.exit) r.exit = s.far_t;
    }
    r.slabs.push_back(s);
  }
  for (const RaySlab& a : r.slabs) {
    if (a.parallel) continue;
    for (const RaySlab& b : r.slabs) {
      if (b.parallel) continue;
      need((a.near_t - b.far_t) * a.speed * b.speed / (a.speed + b.speed),
           std::string("entry into the ") + kAxis[a.axis] + " slab against exit from the " + kAxis[b.axis] + " slab");
    }
    if (r.tmax) need((a.near_t - *r.tmax) * a.speed, std::string("entry into the ") + kAxis[a.axis] + " slab against tmax");
    if (r.tmin) need((*r.tmin - a.far_t) * a.speed, std::string("tmin against exit from the ") + kAxis[a.axis] + " slab");
  }
  r.empty_range = r.tmin && r.tmax && *r.tmin > *r.tmax;
  r.hit = !outside_parallel_slab && !r.empty_range && (!r.enter || !r.exit || *r.enter <= *r.exit);
  return r;
}

template <>
ExactVerdict judge(const harness::RayAabbInput& in) {
  const Ray& ray = in.ray;
  const Aabb& box = in.box;
  const Vec3 &o = ray.origin, &d = ray.dir, &lo = box.lo, &hi = box.hi;
  if (has_nan({o.x, o.y, o.z, d.x, d.y, d.z, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, ray.tmin, ray.tmax})) {
    return documented(false, "NaN input");
  }
  if (!all_finite({o.x, o.y, o.z, d.x, d.y, d.z, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z})) {
    return documented(false, "infinite coordinate");
  }
  if (ray.tmin == INFINITY || ray.tmax == -INFINITY) return documented(false, "tmin = +inf or tmax = -inf");
  if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) return documented(false, "inverted box");
  const double magnitude = max_magnitude({o.x, o.y, o.z, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
  if (auto why = scale_outside(magnitude, -900, 1000)) return unspecified(*why);

  const RayAnalysis r = analyse_ray(in);
  const Rational limit = rational(0x1p1000);
  for (const RaySlab& s : r.slabs) {
    if (!s.parallel && (abs(s.near_t) > limit || abs(s.far_t) > limit)) {
      return unspecified(std::string("slab parameter beyond 2^1000 on axis ") + "xyz"[s.axis]);
    }
  }
  ExactVerdict v;
  v.answer.hit = r.hit;
  if (r.hit) v.answer.params = {r.enter ? to_double(*r.enter) : -INFINITY, r.exit ? to_double(*r.exit) : INFINITY};
  if (r.empty_range) {
    v.margin = -INFINITY;
  } else {
    v.margin = signed_margin(-to_double(r.delta) / scale_of(magnitude), -sgn(r.delta));
    if ((sgn(r.delta) <= 0) != r.hit) {
      v.decided = false;
      v.note = "internal inconsistency: margin and answer disagree";
    }
  }
  if (!r.flushed.empty()) {  // in the domain: the contract defines such a ray as parallel
    v.note = "direction component(s) " + r.flushed + " have an overflowing reciprocal: parallel by contract";
  }
  return v;
}

template <>
harness::Explanation explain(const harness::RayAabbInput& in) {
  using harness::Explanation;
  const RayAnalysis r = analyse_ray(in);
  Explanation e;
  e.title = "slabs: the t interval of each";
  e.columns = {"slab", "dir", "t interval exact", "t interval float", "note"};
  const char* const names[] = {"x", "y", "z"};
  for (const RaySlab& s : r.slabs) {
    const int k = s.axis;
    if (s.parallel) {
      e.rows.push_back({names[k], num(in.ray.dir[k]), "-", "-",
                        std::string("parallel: origin ") + (s.origin_inside ? "inside" : "outside") + " the closed slab"});
      continue;
    }
    const double inv = 1.0 / in.ray.dir[k];
    double t0 = (in.box.lo[k] - in.ray.origin[k]) * inv, t1 = (in.box.hi[k] - in.ray.origin[k]) * inv;
    if (inv < 0) std::swap(t0, t1);
    e.rows.push_back({names[k], num(in.ray.dir[k]), interval(to_double(s.near_t), to_double(s.far_t)), interval(t0, t1), ""});
  }
  e.facts.push_back({"[tmin, tmax]", interval(in.ray.tmin, in.ray.tmax)});
  e.facts.push_back({"t_enter (exact)", r.enter ? num(*r.enter) : "-inf"});
  e.facts.push_back({"t_exit (exact)", r.exit ? num(*r.exit) : "inf"});
  if (!r.flushed.empty()) e.facts.push_back({"parallel by contract", r.flushed});
  e.deciding = r.empty_range ? "tmin > tmax: no parameter at all" : "the box growth needed for contact, bound by " + r.binding;
  e.deciding_value = -to_double(r.delta);
  e.deciding_ulps = in_ulps(e.deciding_value, max_magnitude({in.ray.origin.x, in.ray.origin.y, in.ray.origin.z,
                                                              in.box.lo.x, in.box.lo.y, in.box.lo.z, in.box.hi.x,
                                                              in.box.hi.y, in.box.hi.z}));
  return e;
}

}  // namespace cc::exact
