// A double carried with a bound on its distance from the exact value it stands for: the
// floating-point filter of the exact reference. Each operation adds to its operands' bounds its
// own rounding error, found exactly (TwoSum for sums, a fused multiply-add for products), so
// exact operations on exact values stay exact: a bound of 0 means the value is the exact one.
// Products that reach below 2^-960, where the fused multiply-add's error may itself round,
// add 2^-1072. The bound's own arithmetic (at most five roundings) is covered by inflating it
// by 2^-45. A result that overflows has an infinite or NaN value or bound: callers check
// certain() or finite() before trusting it.
#pragma once

#include <algorithm>
#include <cmath>

#include "collide/vec3.h"

namespace cc::exact {

struct Bounded {
  double v = 0;  // the value computed in floating point
  double e = 0;  // |exact - v| <= e

  /// The exact value's sign is v's: the bound excludes 0. False for NaN.
  bool certain() const { return std::fabs(v) > e; }
  /// The exact value is 0.
  bool zero() const { return v == 0 && e == 0; }
  bool finite() const { return std::isfinite(v) && std::isfinite(e); }
};

namespace bounded_detail {
constexpr double kTiny = 0x1p-960;         // below this a product's error may not be exact
constexpr double kUnderflow = 0x1p-1072;   // four times the largest rounding error below 2^-1022
constexpr double kInflate = 1 + 0x1p-45;  // covers the roundings of the bound's own arithmetic
}  // namespace bounded_detail

inline Bounded operator+(Bounded a, Bounded b) {
  const double s = a.v + b.v;
  const double b_part = s - a.v;
  const double rounding = (a.v - (s - b_part)) + (b.v - b_part);  // a + b - s exactly (TwoSum)
  return {s, (a.e + b.e + std::fabs(rounding)) * bounded_detail::kInflate};
}
inline Bounded operator-(Bounded a) { return {-a.v, a.e}; }
inline Bounded operator-(Bounded a, Bounded b) { return a + -b; }
inline Bounded operator*(Bounded a, Bounded b) {
  using namespace bounded_detail;
  const double p = a.v * b.v;
  const double rounding = std::fma(a.v, b.v, -p);  // a b - p exactly, unless p is tiny
  double e = std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + std::fabs(rounding);
  const bool exact_inputs = a.e == 0 && b.e == 0;
  const bool exact_product = exact_inputs && (a.v == 0 || b.v == 0 || std::fabs(p) >= kTiny);
  if (!exact_product && e < kTiny) e += kUnderflow;
  return {p, e * kInflate};
}
/// min, max and abs move the exact value no further than the bounds of their operands.
inline Bounded min(Bounded a, Bounded b) { return {std::min(a.v, b.v), std::max(a.e, b.e)}; }
inline Bounded max(Bounded a, Bounded b) { return {std::max(a.v, b.v), std::max(a.e, b.e)}; }
inline Bounded abs(Bounded a) { return {std::fabs(a.v), a.e}; }

struct BoundedVec3 {
  Bounded x, y, z;
  Bounded operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

/// A double, or a vector of them, standing for itself: a bound of 0.
inline Bounded exactly(double x) { return {x, 0}; }
inline BoundedVec3 exactly(const Vec3& v) { return {exactly(v.x), exactly(v.y), exactly(v.z)}; }

inline BoundedVec3 operator+(const BoundedVec3& a, const BoundedVec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline BoundedVec3 operator-(const BoundedVec3& a, const BoundedVec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline BoundedVec3 operator*(Bounded s, const BoundedVec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Bounded dot(const BoundedVec3& a, const BoundedVec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline BoundedVec3 cross(const BoundedVec3& a, const BoundedVec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// An interval [lo, hi] that holds the exact Euclidean length of a: lo <= 0 where the
/// floating-point length cannot tell it from 0 (or falls below 2^-900, where a square loses
/// digits to underflow); hi infinite where it overflows.
struct LengthBounds {
  double lo = 0, hi = 0;
};
inline LengthBounds length_bounds(const BoundedVec3& a) {
  // |exact| is within e_x + e_y + e_z of |v|; the computed sqrt of the computed sum of squares
  // is within 4 roundings of |v| (2^-40 is far more), unless the squares underflow.
  const double squares = a.x.v * a.x.v + a.y.v * a.y.v + a.z.v * a.z.v;
  const double n = std::sqrt(squares);
  const double spread = (a.x.e + a.y.e + a.z.e) * bounded_detail::kInflate;
  if (!(squares >= 0x1p-900) || !std::isfinite(n)) return {0, INFINITY};
  return {n * (1 - 0x1p-40) - spread, n * (1 + 0x1p-40) + spread};
}

}  // namespace cc::exact
