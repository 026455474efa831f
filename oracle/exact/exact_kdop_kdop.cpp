// kdop_kdop in exact arithmetic: the exact k-DOPs of the two point sets (the extreme exact
// projections onto each direction) overlap iff they overlap on every slab.
// Margin: the smallest per-slab overlap divided by the length of the slab's direction.
#include "oracle/exact/exact_kdop_kdop.h"

#include <cmath>

#include "collide/kdop.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {

std::vector<ExactSlab> exact_kdop_slabs(const harness::KdopKdopInput& in) {
  std::vector<ExactSlab> slabs;
  for (const KdopDirection& dir : kdop_directions(in.k)) {
    const QVec3 d{dir.x, dir.y, dir.z};
    const auto extent = [&d](const std::vector<Vec3>& points) {
      Rational lo = dot(d, rational(points[0])), hi = lo;
      for (const Vec3& p : points) {
        const Rational s = dot(d, rational(p));
        if (s < lo) lo = s;
        if (s > hi) hi = s;
      }
      return std::pair{lo, hi};
    };
    ExactSlab s;
    std::tie(s.a_lo, s.a_hi) = extent(in.a);
    std::tie(s.b_lo, s.b_hi) = extent(in.b);
    s.overlap = (s.a_hi < s.b_hi ? s.a_hi : s.b_hi) - (s.a_lo > s.b_lo ? s.a_lo : s.b_lo);
    s.length = std::sqrt(static_cast<double>(std::abs(dir.x) + std::abs(dir.y) + std::abs(dir.z)));
    slabs.push_back(s);
  }
  return slabs;
}

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
  bool hit = true;
  for (const ExactSlab& s : exact_kdop_slabs(in)) {
    if (sgn(s.overlap) < 0) hit = false;
    const double m = to_double(s.overlap) / s.length;
    if (!margin || m < *margin) margin = m;
  }
  v.answer.hit = hit;
  v.margin = *margin / scale_of(magnitude);
  return v;
}

}  // namespace cc::exact
