// Small value types for 3-D geometry: a vector and a 3x3 matrix stored by columns.
// Dot products use fp::sum3, so they do not depend on the order of the coordinate axes.
#pragma once

#include "collide/fp.h"

namespace cc {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr Vec3() = default;
  constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  friend constexpr bool operator==(const Vec3&, const Vec3&) = default;
};

constexpr Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
constexpr Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }

/// a . b, with the three products summed by fp::sum3.
inline double dot(const Vec3& a, const Vec3& b) { return fp::sum3(a.x * b.x, a.y * b.y, a.z * b.z); }

/// a . b summed left to right: faster than dot(), but permuting the axes may change its rounding.
/// For choices only, or for bounds that hold in any order of summation.
inline double dot_in_order(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// a x b. Each component is one difference of two products, so permuting or flipping the axes
/// permutes or negates the components exactly.
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// Componentwise absolute value.
inline Vec3 abs(const Vec3& a) { return {std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}; }

/// |a.x| + |a.y| + |a.z| (by fp::sum3): an upper bound of the Euclidean length, up to rounding.
inline double norm1(const Vec3& a) { return fp::sum3(std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)); }

/// max(|a.x|, |a.y|, |a.z|).
inline double max_abs(const Vec3& a) { return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}); }

/// a times the power of two that brings its largest |component| into [1, 2); 0 stays 0. A
/// direction only: axes built from scaled edges do not underflow however short the edges are,
/// and the scaled vector is the same after permuting, flipping or scaling the inputs by 2^k.
inline Vec3 unit_scaled(const Vec3& a) {
  const double m = max_abs(a);
  if (m == 0 || !std::isfinite(m)) return a;
  const int e = fp::exponent_of(m);
  return {fp::scale2(a.x, -e), fp::scale2(a.y, -e), fp::scale2(a.z, -e)};
}

/// a before b in lexicographic order (x, then y, then z): along a line, the order of the points.
inline bool lexicographic_less(const Vec3& a, const Vec3& b) {
  return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
}

/// True when no component is NaN or infinite.
/// (x - x is 0 for a finite x and NaN else: one comparison, no branch per component.)
inline bool finite(const Vec3& a) { return (a.x - a.x) + (a.y - a.y) + (a.z - a.z) == 0; }

/// A 3x3 matrix stored as three columns.
struct Mat3 {
  Vec3 col[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

  static constexpr Mat3 identity() { return {}; }
  static constexpr Mat3 from_columns(const Vec3& c0, const Vec3& c1, const Vec3& c2) {
    Mat3 m;
    m.col[0] = c0;
    m.col[1] = c1;
    m.col[2] = c2;
    return m;
  }

  /// Entry in row r, column c.
  constexpr double operator()(int r, int c) const { return col[c][r]; }
  constexpr double& operator()(int r, int c) { return col[c][r]; }
  constexpr Vec3 row(int r) const { return {col[0][r], col[1][r], col[2][r]}; }

  friend constexpr bool operator==(const Mat3&, const Mat3&) = default;
};

/// M v.
inline Vec3 operator*(const Mat3& m, const Vec3& v) {
  return {dot(m.row(0), v), dot(m.row(1), v), dot(m.row(2), v)};
}

/// M^T v: the coordinates of v along the columns of M.
inline Vec3 transpose_times(const Mat3& m, const Vec3& v) {
  return {dot(m.col[0], v), dot(m.col[1], v), dot(m.col[2], v)};
}

/// True when no entry is NaN or infinite.
inline bool finite(const Mat3& m) {
  const Vec3 zero = (m.col[0] - m.col[0]) + (m.col[1] - m.col[1]) + (m.col[2] - m.col[2]);
  return finite(zero);
}

}  // namespace cc
