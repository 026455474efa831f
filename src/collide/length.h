// Euclidean lengths and directions that neither overflow nor underflow, for the distance queries.
#pragma once

#include <cmath>

#include "collide/fp.h"
#include "collide/vec3.h"

namespace cc {

/// v times 2^-e, component by component (exact unless a component leaves the normal range).
inline Vec3 scaled(const Vec3& v, int e) { return {fp::scale2(v.x, -e), fp::scale2(v.y, -e), fp::scale2(v.z, -e)}; }

/// v as its length is measured: v itself when its largest component lies in [2^-500, 2^500]
/// (no square overflows, the largest is normal, and those that underflow err by 2^-1074
/// against a sum of at least 2^-1000), else v times 2^-exponent with its largest component in
/// [1, 2) (exact). For finite v; a zero v is itself. The common case is told by the sum of
/// squares alone: one in [2^-998, 2^1000] puts the largest component in [2^-500, 2^500].
struct MeasuredVector {
  Vec3 v;
  int exponent = 0;
  double sum_of_squares;  // of v, in an order-free sum (fp::sum3)
  explicit MeasuredVector(const Vec3& w) : v(w), sum_of_squares(squares(w)) {
    if (sum_of_squares >= 0x1p-998 && sum_of_squares <= 0x1p1000) return;
    const double m = max_abs(w);
    if (m > 0 && (m < 0x1p-500 || m > 0x1p500)) {
      exponent = fp::exponent_of(m), v = scaled(w, exponent), sum_of_squares = squares(v);
    }
  }
  /// The measured vector's length (within 2.6u: a three-term sum of squares 3u, the square root
  /// u/2 more).
  double root() const { return std::sqrt(sum_of_squares); }

 private:
  static double squares(const Vec3& u) { return fp::sum3(u.x * u.x, u.y * u.y, u.z * u.z); }
};

/// |v| for finite v: within 2.6u, but for the scaling back, exact unless the length is subnormal.
inline double length(const Vec3& v) {
  const MeasuredVector m(v);
  return fp::scale2(m.root(), m.exponent);
}

/// |v| and v / |v| for finite v: the length as length() gives it, each component of the
/// direction within 2u more (a reciprocal and a product). A zero v has length 0 and no
/// direction (zero).
struct LengthAndDirection {
  double length = 0;
  Vec3 direction;
};
inline LengthAndDirection length_and_direction(const Vec3& v) {
  const MeasuredVector m(v);
  const double n = m.root();
  if (!(n > 0)) return {};
  const double inverse = 1 / n;
  return {fp::scale2(n, m.exponent), {m.v.x * inverse, m.v.y * inverse, m.v.z * inverse}};
}

}  // namespace cc
