#include "oracle/exact/exact_sweep.h"

#include <algorithm>

namespace cc::exact {

void ExactWindow::restrict(const Rational& p, const Rational& s, const Rational& r) {
  if (sgn(s) == 0) {
    if (abs(p) > r) first = 1, last = 0;
    return;
  }
  Rational enter = (-r - p) / s, exit = (r - p) / s;
  if (sgn(s) < 0) std::swap(enter, exit);
  first = std::max(first, enter);
  last = std::min(last, exit);
}

std::vector<MovingAxis> moving_axes(const MovingObb& a, const MovingObb& b) {
  const ExactShape sa = parallelepiped_shape(a.box.center, a.box.half, a.box.axes, "A");
  const ExactShape sb = parallelepiped_shape(b.box.center, b.box.half, b.box.axes, "B");
  const QVec3 d = sb.center - sa.center;
  const QVec3 w = rational(b.velocity) - rational(a.velocity);
  std::vector<MovingAxis> out;
  for (CandidateAxis& c : candidate_axes_for_any_offset(sa, sb)) {
    Rational r = 0;
    for (const QVec3& h : sa.half_edges) r += abs(dot(c.axis, h));
    for (const QVec3& h : sb.half_edges) r += abs(dot(c.axis, h));
    const Rational p = dot(c.axis, d), s = dot(c.axis, w);
    out.push_back({std::move(c), p, s, r});
  }
  return out;
}

ExactWindow exact_sweep(const std::vector<MovingAxis>& axes, const Rational& grow) {
  ExactWindow window;
  for (const MovingAxis& m : axes) {
    if (sgn(grow) == 0) {
      window.restrict(m.p, m.s, m.r);
    } else {
      window.restrict(m.p, m.s, m.r + grow * rational(m.axis.conditioning.to_double()));
    }
    if (!window.hit()) break;
  }
  return window;
}

ExactWindow exact_sweep(const Aabb& a, const Vec3& va, const Aabb& b, const Vec3& vb) {
  ExactWindow window;
  for (int k = 0; k < 3; ++k) {
    // a.lo - b.hi <= t w <= a.hi - b.lo, as |p + t s| <= r with the centre and half width.
    const Rational low = rational(a.lo[k]) - rational(b.hi[k]);
    const Rational high = rational(a.hi[k]) - rational(b.lo[k]);
    const Rational w = rational(vb[k]) - rational(va[k]);
    window.restrict(-(low + high) / 2, w, (high - low) / 2);
  }
  return window;
}

}  // namespace cc::exact
