// Euclidean lengths and directions that neither overflow nor underflow, for the distance queries.
#pragma once

#include <cmath>

#include "collide/fp.h"
#include "collide/vec3.h"

namespace cc {

/// v times 2^-e, component by component (exact unless a component leaves the normal range).
inline Vec3 scaled(const Vec3& v, int e) { return {fp::scale2(v.x, -e), fp::scale2(v.y, -e), fp::scale2(v.z, -e)}; }

/// |v| and v / |v|: the length within 2.6u of |v| (three-term sum of squares 3u, square root
/// u/2 more), each component of the direction within 2u more (a reciprocal and a product).
/// When the largest component lies in [2^-500, 2^500] the squares are taken as they are: none
/// overflows, the largest is normal, and those that underflow err by 2^-1074 against a sum of
/// at least 2^-1000. Otherwise v is first scaled by the power of two that brings its largest
/// component into [1, 2), exactly, and the length scaled back (exact unless subnormal). A zero
/// v has length 0 and no direction (zero); a non-finite one, a non-finite length.
struct LengthAndDirection {
  double length = 0;
  Vec3 direction;
};
inline LengthAndDirection length_and_direction(const Vec3& v) {
  const double m = max_abs(v);
  if (m >= 0x1p-500 && m <= 0x1p500) {
    const double n = std::sqrt(fp::sum3(v.x * v.x, v.y * v.y, v.z * v.z));
    const double inverse = 1 / n;
    return {n, {v.x * inverse, v.y * inverse, v.z * inverse}};
  }
  if (m == 0) return {};
  if (!std::isfinite(m)) return {m, {}};
  const int e = fp::exponent_of(m);
  const Vec3 s = scaled(v, e);
  const double n = std::sqrt(fp::sum3(s.x * s.x, s.y * s.y, s.z * s.z));
  const double inverse = 1 / n;
  return {fp::scale2(n, e), {s.x * inverse, s.y * inverse, s.z * inverse}};
}

/// |v| alone, as length_and_direction computes it.
inline double length(const Vec3& v) {
  const double m = max_abs(v);
  if (m >= 0x1p-500 && m <= 0x1p500) return std::sqrt(fp::sum3(v.x * v.x, v.y * v.y, v.z * v.z));
  if (m == 0 || !std::isfinite(m)) return m;
  const int e = fp::exponent_of(m);
  const Vec3 s = scaled(v, e);
  return fp::scale2(std::sqrt(fp::sum3(s.x * s.x, s.y * s.y, s.z * s.z)), e);
}

}  // namespace cc
