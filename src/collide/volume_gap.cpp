#include "collide/volume_gap.h"

#include <algorithm>
#include <cmath>

#include "collide/fp.h"
#include "collide/length.h"

namespace cc {
namespace {

// The gap between the projections of a and b on n, over |n|, less its rounding; 0 where they
// overlap on n or n is zero. The projections' radii are sums of h_i |n . axis_i| (exact for the
// parallelepipeds). With d = b.center - a.center rounded (u of each |d_k|), the numerator
// |n . d| - sum h_i |n . a_i| - sum h_j |n . b_j| sums seven terms, each a three-term dot (3u of
// its terms' absolute sum) times at most one half extent (u): within 10u of `magnitude`, the
// absolute sum of every product (computed 12u low at most), plus the slack of some twenty
// products that may underflow: 16u magnitude + 32 slack is taken. |n| is within 2.6u; the
// quotient rounds by u more: the result is lowered by 8u of itself.
double gap_along(const Obb& a, const Obb& b, const Vec3& d, const Vec3& n) {
  const auto term = [&n](const Vec3& v, double& magnitude) {
    magnitude += std::fabs(n.x * v.x) + std::fabs(n.y * v.y) + std::fabs(n.z * v.z);
    return std::fabs(n.x * v.x + n.y * v.y + n.z * v.z);
  };
  double magnitude = 0;
  double gap = term(d, magnitude);
  for (int i = 0; i < 3; ++i) {
    double ma = 0, mb = 0;
    gap -= a.half[i] * term(a.axes.col[i], ma) + b.half[i] * term(b.axes.col[i], mb);
    magnitude += a.half[i] * ma + b.half[i] * mb;
  }
  const double certain = gap - (16 * fp::u * magnitude + 32 * fp::subnormal_slack);
  if (!(certain > 0)) return 0;  // overlapping on n, or NaN input
  const double n_length = length(n);
  if (!(n_length > 0)) return 0;
  return certain / n_length * (1 - 8 * fp::u);
}

}  // namespace

double volume_gap(const Sphere& a, const Sphere& b) {
  // |d| within 3.6u (d's rounding and length's 2.6u), the radii's sum u, each product u and the
  // difference u: margins of 2^-48 on both sides cover them.
  const double gap = length(b.center - a.center) * (1 - 0x1p-48) - (a.radius + b.radius) * (1 + 0x1p-48) -
                     fp::subnormal_slack;
  return gap > 0 ? gap : 0;  // 0 for NaN input too
}

double volume_gap(const Obb& a, const Obb& b) {
  const Vec3 d = b.center - a.center;
  double best = gap_along(a, b, d, d);
  for (int i = 0; i < 3; ++i) {
    best = std::max({best, gap_along(a, b, d, a.axes.col[i]), gap_along(a, b, d, b.axes.col[i])});
  }
  return best;
}

}  // namespace cc
