// Cross products within a few ulps however nearly parallel their vectors are, and the exact
// difference of two points they can be taken of.
#pragma once

#include <cmath>

#include "collide/length.h"
#include "collide/vec3.h"

namespace cc {

/// a d - b c within 2u of its exact value (Kahan's difference of products: b c's rounding error,
/// exact by a fused multiply-add, put back), and exactly 0 when it is 0; but for underflow.
inline double difference_of_products(double a, double d, double b, double c) {
  const double w = b * c;
  const double e = std::fma(-b, c, w);
  const double f = std::fma(a, d, -w);
  return f + e;
}

/// a x b, each component within 2u of the exact one however nearly parallel a and b are (the
/// plain cross product errs by u of the products, which is all of it for nearly parallel
/// vectors); b x a is its exact negation. Underflow adds up to 2^-1073 per component.
inline Vec3 accurate_cross(const Vec3& a, const Vec3& b) {
  if (lexicographic_less(b, a)) return -accurate_cross(b, a);
  return {difference_of_products(a.y, b.z, a.z, b.y), difference_of_products(a.z, b.x, a.x, b.z),
          difference_of_products(a.x, b.y, a.y, b.x)};
}

/// p - q exactly, as hi + lo: hi the rounded difference, lo its rounding error (Knuth's two-sum,
/// exact for finite p and q whose difference does not overflow).
struct ExactDifference {
  Vec3 hi, lo;
};
inline ExactDifference exact_difference(const Vec3& p, const Vec3& q) {
  ExactDifference d;
  for (int k = 0; k < 3; ++k) {
    const double s = p[k] - q[k];
    const double minus_q = s - p[k];  // the part of -q that s holds
    const double of_p = s - minus_q;  // and the part of p
    d.hi[k] = s;
    d.lo[k] = (p[k] - of_p) - (q[k] + minus_q);
  }
  return d;
}

/// The difference times 2^-e, e the exponent of hi's largest component (so that it lies in
/// [1, 2)): exact but for lo's components below 2^-1022 of hi's largest, lost to underflow. A
/// zero difference stays zero.
inline ExactDifference unit_scaled(const ExactDifference& d) {
  const double m = max_abs(d.hi);
  if (m == 0 || !std::isfinite(m)) return d;
  const int e = fp::exponent_of(m);
  return {scaled(d.hi, e), scaled(d.lo, e)};
}

/// (a.hi + a.lo) x b: a.hi x b accurately, a.lo x b plainly (it is u of the whole at most).
/// Each component within 3u of the exact one plus 4u^2 |a.hi|_inf |b|_inf, and underflow's
/// 2^-1072.
inline Vec3 accurate_cross(const ExactDifference& a, const Vec3& b) { return accurate_cross(a.hi, b) + cross(a.lo, b); }

/// (a.hi + a.lo) x (b.hi + b.lo), a.lo x b.lo (u^2 of the whole at most) left out. Each
/// component within 3u of the exact one plus 8u^2 |a.hi|_inf |b.hi|_inf, and underflow's
/// 2^-1072.
inline Vec3 accurate_cross(const ExactDifference& a, const ExactDifference& b) {
  return accurate_cross(a.hi, b.hi) + (cross(a.hi, b.lo) + cross(a.lo, b.hi));
}

}  // namespace cc
