#include "collide/volume_gap.h"

#include <algorithm>
#include <cmath>

#include "collide/fp.h"
#include "collide/length.h"

namespace cc {
namespace {

double sum_abs(const Vec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }

// The gap along a direction n, given its numerator |n . d| - sum h_i |n . a_i| - sum h_j |n . b_j|
// (d = b.center - a.center) computed from three-term dots, n . n, and the largest |n_k|.
// Rounding: d's components (u each), each dot (3u of the absolute sum of its products), each
// product by a half extent (u) and the seven-term sum (6u): within 10u of sum_k |n_k| (|d_k| +
// sum h_i |a_ik| + sum h_j |b_jk|) <= max_k |n_k| S, S = |d|_1 + sum h_i |a_i|_1 + sum h_j |b_j|_1
// (computed 4u low at most); 16u max_k |n_k| S is taken, plus the slack of the products that may
// underflow. |n| = sqrt(n . n) within 2.6u where n . n is normal; the quotient rounds by u: the
// result is lowered by 8u of itself. Where n . n is below 2^-900 (its terms may have underflowed)
// |n| is measured by length() instead.
double gap_along(double numerator, double n_squared, double n_largest, double s, const Vec3& n) {
  const double certain = numerator - (16 * fp::u * n_largest * s + 64 * fp::subnormal_slack);
  if (!(certain > 0)) return 0;  // overlapping along n, or NaN input
  const double n_length = n_squared >= 0x1p-900 ? std::sqrt(n_squared) : length(n);
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
  const Vec3* ax = a.axes.col;
  const Vec3* bx = b.axes.col;
  // Every dot the seven directions need, once: a_i . a_j, b_i . b_j, a_i . b_j, a_i . d, b_j . d.
  double aa[3][3], bb[3][3], ab[3][3], ad[3], bd[3];
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) aa[i][j] = aa[j][i] = dot_in_order(ax[i], ax[j]), bb[i][j] = bb[j][i] = dot_in_order(bx[i], bx[j]);
    for (int j = 0; j < 3; ++j) ab[i][j] = dot_in_order(ax[i], bx[j]);
    ad[i] = dot_in_order(ax[i], d), bd[i] = dot_in_order(bx[i], d);
  }
  double s = sum_abs(d);
  for (int i = 0; i < 3; ++i) s += a.half[i] * sum_abs(ax[i]) + b.half[i] * sum_abs(bx[i]);
  const auto radius_a = [&](const double* along_a) {
    return a.half[0] * std::fabs(along_a[0]) + a.half[1] * std::fabs(along_a[1]) + a.half[2] * std::fabs(along_a[2]);
  };
  const auto radius_b = [&](const double* along_b) {
    return b.half[0] * std::fabs(along_b[0]) + b.half[1] * std::fabs(along_b[1]) + b.half[2] * std::fabs(along_b[2]);
  };
  // The line of the centres.
  double best = gap_along(dot_in_order(d, d) - radius_a(ad) - radius_b(bd), dot_in_order(d, d), max_abs(d), s, d);
  for (int i = 0; i < 3; ++i) {
    // a's axis i, and b's.
    const double ba[3] = {ab[0][i], ab[1][i], ab[2][i]};
    best = std::max(best, gap_along(std::fabs(ad[i]) - radius_a(aa[i]) - radius_b(ab[i]), aa[i][i], max_abs(ax[i]), s, ax[i]));
    best = std::max(best, gap_along(std::fabs(bd[i]) - radius_a(ba) - radius_b(bb[i]), bb[i][i], max_abs(bx[i]), s, bx[i]));
  }
  return best;
}

}  // namespace cc
