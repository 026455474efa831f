// kdop_kdop in exact arithmetic: the exact k-DOPs of the two point sets (the extreme exact
// projections onto each direction) overlap iff they overlap on every slab.
// Margin: the smallest per-slab overlap divided by the length of the slab's direction.
#include <algorithm>
#include <cmath>

#include "collide/kdop.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/exact_kdops.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {

template <>
ExactVerdict judge(const harness::KdopKdopInput& in) {
  double magnitude = 0;
  for (const auto* set : {&in.a, &in.b}) {
    for (const Vec3& p : *set) {
      if (!all_finite({p.x, p.y, p.z})) return documented(false, "NaN or infinite coordinate");
      magnitude = std::max(magnitude, max_abs(p));
    }
  }
  if (!is_supported_kdop(in.k)) return unspecified("no direction set for k = " + std::to_string(in.k));
  if (auto why = scale_outside(magnitude, -1074, 1000)) return unspecified(*why);
  ExactVerdict v;
  if (in.a.empty() || in.b.empty()) {
    v.answer.hit = false;
    v.margin = -INFINITY;
    return v;
  }
  std::optional<double> margin;
  int sign = 1;  // the exact sign of the smallest overlap
  for (const ExactSlab& s : exact_kdop_slabs(in.k, in.a, in.b)) {
    sign = std::min(sign, sgn(s.overlap));
    const double m = to_double(s.overlap) / s.length;
    if (!margin || m < *margin) margin = m;
  }
  v.answer.hit = sign >= 0;
  v.margin = signed_margin(*margin / scale_of(magnitude), sign);
  return v;
}

template <>
harness::Explanation explain(const harness::KdopKdopInput& in) {
  using harness::Explanation;
  Explanation e;
  e.title = "slabs of the exact k-DOPs and of the library's fitted ones";
  e.columns = {"direction", "A exact", "B exact", "overlap exact", "A fitted", "B fitted"};
  bool finite_points = !in.a.empty() && !in.b.empty();
  for (const auto* set : {&in.a, &in.b}) {
    for (const Vec3& p : *set) finite_points &= finite(p);
  }
  if (!finite_points || !is_supported_kdop(in.k)) return e;
  const auto slabs = exact_kdop_slabs(in.k, in.a, in.b);
  const auto dirs = kdop_directions(in.k);
  // The library's fitted slabs, through a runtime dispatch on k.
  std::vector<double> alo, ahi, blo, bhi;
  const auto fitted = [&](auto dop_a, auto dop_b) {
    alo.assign(dop_a.lo.begin(), dop_a.lo.end()), ahi.assign(dop_a.hi.begin(), dop_a.hi.end());
    blo.assign(dop_b.lo.begin(), dop_b.lo.end()), bhi.assign(dop_b.hi.begin(), dop_b.hi.end());
  };
  switch (in.k) {
    case 6: fitted(fit_kdop<6>(in.a), fit_kdop<6>(in.b)); break;
    case 14: fitted(fit_kdop<14>(in.a), fit_kdop<14>(in.b)); break;
    case 16: fitted(fit_kdop<16>(in.a), fit_kdop<16>(in.b)); break;
    case 18: fitted(fit_kdop<18>(in.a), fit_kdop<18>(in.b)); break;
    case 24: fitted(fit_kdop<24>(in.a), fit_kdop<24>(in.b)); break;
    default: fitted(fit_kdop<26>(in.a), fit_kdop<26>(in.b));
  }
  double worst = INFINITY;
  for (std::size_t i = 0; i < slabs.size(); ++i) {
    const ExactSlab& s = slabs[i];
    const Vec3 d{static_cast<double>(dirs[i].x), static_cast<double>(dirs[i].y), static_cast<double>(dirs[i].z)};
    e.rows.push_back({vec(d), interval(to_double(s.a_lo), to_double(s.a_hi)), interval(to_double(s.b_lo), to_double(s.b_hi)),
                      num(s.overlap), interval(alo[i], ahi[i]), interval(blo[i], bhi[i])});
    const double m = to_double(s.overlap) / s.length;
    if (m < worst) {
      worst = m, e.deciding_row = static_cast<int>(i);
      e.axis = d;
      e.a_lo = to_double(s.a_lo), e.a_hi = to_double(s.a_hi), e.b_lo = to_double(s.b_lo), e.b_hi = to_double(s.b_hi);
      e.deciding_value = to_double(s.overlap);
      e.deciding_ulps = in_ulps(e.deciding_value, std::max({std::fabs(e.a_lo), std::fabs(e.a_hi), std::fabs(e.b_lo),
                                                            std::fabs(e.b_hi)}));
    }
  }
  e.deciding = "the smallest overlap over the slabs (exact k-DOPs)";
  return e;
}

}  // namespace cc::exact
