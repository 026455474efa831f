// sphere_sphere in exact arithmetic: the balls meet iff |c_a - c_b|^2 <= (r_a + r_b)^2.
// Margin: r_a + r_b - |c_a - c_b|, computed as ((r_a+r_b)^2 - |c_a-c_b|^2) / (r_a + r_b + |c_a-c_b|)
// so that its relative accuracy does not suffer from cancellation.
#include <algorithm>
#include <cmath>

#include "oracle/exact/domain.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"
#include "oracle/exact/rational.h"

namespace cc::exact {
template <>
ExactVerdict judge(const harness::SphereSphereInput& in) {
  const Sphere &a = in.a, &b = in.b;
  const std::initializer_list<double> all = {a.center.x, a.center.y, a.center.z, a.radius,
                                             b.center.x, b.center.y, b.center.z, b.radius};
  if (!all_finite(all)) return documented(false, "NaN or infinite input");
  if (a.radius < 0 || b.radius < 0) return documented(false, "negative radius");
  const double magnitude = max_magnitude(all);
  const QVec3 d = rational(a.center) - rational(b.center);
  const Rational dist2 = dot(d, d);
  const Rational reach = rational(a.radius) + rational(b.radius);
  const Rational slack = reach * reach - dist2;

  ExactVerdict v;
  v.answer.hit = sgn(slack) >= 0;
  if (auto why = scale_outside(magnitude, -500, 500)) {
    // Decided all the same, the same margin computed with exponents kept apart, so that it
    // neither underflows nor overflows.
    const Magnitude scale = Magnitude::of(rational(scale_of(magnitude)));
    const Magnitude denominator = Magnitude::of(reach) + length(d);
    v.margin = sgn(slack) == 0 ? 0.0 : (Magnitude::of(slack) / denominator / scale).to_double();
    return beyond_range(v, *why);
  }
  const double denominator = to_double(reach) + length(d).to_double();
  v.margin = signed_margin(denominator > 0 ? to_double(slack) / denominator / scale_of(magnitude) : 0.0, sgn(slack));
  return v;
}

template <>
harness::Explanation explain(const harness::SphereSphereInput& in) {
  using harness::Explanation;
  Explanation e;
  const QVec3 d = rational(in.a.center) - rational(in.b.center);
  const Rational reach = rational(in.a.radius) + rational(in.b.radius);
  const Rational slack = reach * reach - dot(d, d);
  const Vec3 fd = in.a.center - in.b.center;
  const double fd2 = fd.x * fd.x + fd.y * fd.y + fd.z * fd.z, fr = in.a.radius + in.b.radius;
  e.title = "distances";
  e.facts = {{"|c_a - c_b|", num(length(d).to_double())},
             {"r_a + r_b", num(reach)},
             {"(r_a + r_b)^2 - |c_a - c_b|^2 exact", num(slack)},
             {"(r_a + r_b)^2 - |c_a - c_b|^2 float", num(fr * fr - fd2)}};
  e.deciding = "(r_a + r_b)^2 - |c_a - c_b|^2";
  e.deciding_value = to_double(slack);
  e.deciding_ulps = in_ulps(e.deciding_value, std::max(to_double(reach * reach), to_double(dot(d, d))));
  return e;
}

}  // namespace cc::exact
