// Lanes of doubles: the interface the library's SIMD kernels are written against, so that one
// kernel source builds every kernel. A kernel is a template over a lane set L (Scalar: 1 lane,
// Avx2: 4, Avx512: 8) using only what is below: L::D holds L::kWidth doubles, L::M one flag per
// lane. Each instruction set's entry point is a function with that set's target attribute and
// [[gnu::flatten]], which inlines the kernel into it, so the kernel's arithmetic is compiled for
// that set (see dispatch() below). Every lane computes exactly what the scalar kernel computes,
// one IEEE double operation for one, so the kernels give the same answers bit for bit:
//  - min(a, b) is a < b ? a : b and max(a, b) is a > b ? a : b, as the vector instructions define
//    them (b when either is NaN, and when a and b are zeros of either sign): not std::min;
//  - comparisons are ordered and quiet (false when either operand is NaN).
#pragma once

#include <immintrin.h>

#include <bit>
#include <cstdint>

#include "collide/simd.h"
#include "collide/vec3.h"

static_assert(sizeof(cc::Vec3) == 3 * sizeof(double), "a Vec3 is its three coordinates, loaded as such");

// The vector types are passed by value between functions that flatten inlines: GCC's note that
// doing so without AVX enabled would change the calling convention concerns calls that never
// remain.
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace cc::simd {

/// One lane: the scalar kernel, and the tails of the vector kernels.
struct Scalar {
  static constexpr int kWidth = 1;
  struct D {
    double v;
  };
  struct M {
    bool m;
  };
  static D load(const double* p) { return {*p}; }
  static D broadcast(double x) { return {x}; }
  static void store(double* p, D a) { *p = a.v; }
  static D min(D a, D b) { return {a.v < b.v ? a.v : b.v}; }
  static D max(D a, D b) { return {a.v > b.v ? a.v : b.v}; }
  static D abs(D a) { return {std::bit_cast<double>(std::bit_cast<std::uint64_t>(a.v) & ~(std::uint64_t{1} << 63))}; }
  static D select(M m, D yes, D no) { return m.m ? yes : no; }
  /// Bit i set when lane i's flag is.
  static unsigned bits(M m) { return m.m ? 1u : 0u; }
};
inline Scalar::D operator+(Scalar::D a, Scalar::D b) { return {a.v + b.v}; }
inline Scalar::D operator-(Scalar::D a, Scalar::D b) { return {a.v - b.v}; }
inline Scalar::D operator*(Scalar::D a, Scalar::D b) { return {a.v * b.v}; }
inline Scalar::M operator<(Scalar::D a, Scalar::D b) { return {a.v < b.v}; }
inline Scalar::M operator<=(Scalar::D a, Scalar::D b) { return {a.v <= b.v}; }
inline Scalar::M operator>(Scalar::D a, Scalar::D b) { return {a.v > b.v}; }
inline Scalar::M operator>=(Scalar::D a, Scalar::D b) { return {a.v >= b.v}; }
inline Scalar::M operator&(Scalar::M a, Scalar::M b) { return {a.m && b.m}; }
inline Scalar::M operator|(Scalar::M a, Scalar::M b) { return {a.m || b.m}; }

/// Four lanes (AVX2).
struct Avx2 {
  static constexpr int kWidth = 4;
  struct D {
    __m256d v;
  };
  struct M {
    __m256d m;
  };
  [[gnu::target("avx2")]] static D load(const double* p) { return {_mm256_loadu_pd(p)}; }
  [[gnu::target("avx2")]] static D broadcast(double x) { return {_mm256_set1_pd(x)}; }
  [[gnu::target("avx2")]] static void store(double* p, D a) { _mm256_storeu_pd(p, a.v); }
  [[gnu::target("avx2")]] static D min(D a, D b) { return {_mm256_min_pd(a.v, b.v)}; }
  [[gnu::target("avx2")]] static D max(D a, D b) { return {_mm256_max_pd(a.v, b.v)}; }
  [[gnu::target("avx2")]] static D abs(D a) { return {_mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v)}; }
  [[gnu::target("avx2")]] static D select(M m, D yes, D no) { return {_mm256_blendv_pd(no.v, yes.v, m.m)}; }
  [[gnu::target("avx2")]] static unsigned bits(M m) { return static_cast<unsigned>(_mm256_movemask_pd(m.m)); }
};
[[gnu::target("avx2")]] inline Avx2::D operator+(Avx2::D a, Avx2::D b) { return {_mm256_add_pd(a.v, b.v)}; }
[[gnu::target("avx2")]] inline Avx2::D operator-(Avx2::D a, Avx2::D b) { return {_mm256_sub_pd(a.v, b.v)}; }
[[gnu::target("avx2")]] inline Avx2::D operator*(Avx2::D a, Avx2::D b) { return {_mm256_mul_pd(a.v, b.v)}; }
[[gnu::target("avx2")]] inline Avx2::M operator<(Avx2::D a, Avx2::D b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)}; }
[[gnu::target("avx2")]] inline Avx2::M operator<=(Avx2::D a, Avx2::D b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LE_OQ)}; }
[[gnu::target("avx2")]] inline Avx2::M operator>(Avx2::D a, Avx2::D b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ)}; }
[[gnu::target("avx2")]] inline Avx2::M operator>=(Avx2::D a, Avx2::D b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GE_OQ)}; }
[[gnu::target("avx2")]] inline Avx2::M operator&(Avx2::M a, Avx2::M b) { return {_mm256_and_pd(a.m, b.m)}; }
[[gnu::target("avx2")]] inline Avx2::M operator|(Avx2::M a, Avx2::M b) { return {_mm256_or_pd(a.m, b.m)}; }

/// Eight lanes (AVX-512 F and DQ; the kernel also takes VL, for the triples below).
struct Avx512 {
  static constexpr int kWidth = 8;
  struct D {
    __m512d v;
  };
  struct M {
    __mmask8 m;
  };
  [[gnu::target("avx512f,avx512dq")]] static D load(const double* p) { return {_mm512_loadu_pd(p)}; }
  [[gnu::target("avx512f,avx512dq")]] static D broadcast(double x) { return {_mm512_set1_pd(x)}; }
  [[gnu::target("avx512f,avx512dq")]] static void store(double* p, D a) { _mm512_storeu_pd(p, a.v); }
  // (Written with a mask: GCC 12's _mm512_min_pd and _mm512_max_pd pass an undefined source
  // operand, which -Wmaybe-uninitialized reports wherever they are inlined.)
  [[gnu::target("avx512f,avx512dq")]] static D min(D a, D b) { return {_mm512_mask_min_pd(a.v, 0xFF, a.v, b.v)}; }
  [[gnu::target("avx512f,avx512dq")]] static D max(D a, D b) { return {_mm512_mask_max_pd(a.v, 0xFF, a.v, b.v)}; }
  [[gnu::target("avx512f,avx512dq")]] static D abs(D a) { return {_mm512_abs_pd(a.v)}; }
  [[gnu::target("avx512f,avx512dq")]] static D select(M m, D yes, D no) { return {_mm512_mask_blend_pd(m.m, no.v, yes.v)}; }
  [[gnu::target("avx512f,avx512dq")]] static unsigned bits(M m) { return m.m; }
};
[[gnu::target("avx512f,avx512dq")]] inline Avx512::D operator+(Avx512::D a, Avx512::D b) { return {_mm512_add_pd(a.v, b.v)}; }
[[gnu::target("avx512f,avx512dq")]] inline Avx512::D operator-(Avx512::D a, Avx512::D b) { return {_mm512_sub_pd(a.v, b.v)}; }
[[gnu::target("avx512f,avx512dq")]] inline Avx512::D operator*(Avx512::D a, Avx512::D b) { return {_mm512_mul_pd(a.v, b.v)}; }
[[gnu::target("avx512f,avx512dq")]] inline Avx512::M operator<(Avx512::D a, Avx512::D b) {
  return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ)};
}
[[gnu::target("avx512f,avx512dq")]] inline Avx512::M operator<=(Avx512::D a, Avx512::D b) {
  return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LE_OQ)};
}
[[gnu::target("avx512f,avx512dq")]] inline Avx512::M operator>(Avx512::D a, Avx512::D b) {
  return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GT_OQ)};
}
[[gnu::target("avx512f,avx512dq")]] inline Avx512::M operator>=(Avx512::D a, Avx512::D b) {
  return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GE_OQ)};
}
[[gnu::target("avx512f,avx512dq")]] inline Avx512::M operator&(Avx512::M a, Avx512::M b) {
  return {static_cast<__mmask8>(a.m & b.m)};
}
[[gnu::target("avx512f,avx512dq")]] inline Avx512::M operator|(Avx512::M a, Avx512::M b) {
  return {static_cast<__mmask8>(a.m | b.m)};
}

/// Three doubles, lane k holding the quantity of index k (of a box's three axes, a triangle's
/// three edges): the kernels that go over the 3 x 3 pairs of two such sets, three pairs at a time,
/// are templates over Triple<Scalar> (three scalar lanes) and Triple<Avx2> (one AVX2 register,
/// its fourth lane unused: whatever it holds, bits() leaves it out). Operations are lane by lane
/// except rotate1 and rotate2, which bring lane k + 1 and k + 2 (mod 3) to lane k; bits() has bit
/// k for lane k.
template <class L>
struct Triple;

template <>
struct Triple<Scalar> {
  double v[3];
  struct M {
    bool m[3];
  };
  static Triple set(double x, double y, double z) { return {{x, y, z}}; }
  static Triple load(const Vec3& p) { return {{p.x, p.y, p.z}}; }
  /// Lanes to rows: row k of the result holds lane k of a, b, c.
  static void transpose(const Triple& a, const Triple& b, const Triple& c, Triple* rows) {
    for (int k = 0; k < 3; ++k) rows[k] = {{a.v[k], b.v[k], c.v[k]}};
  }
  static Triple broadcast(double x) { return {{x, x, x}}; }
  static Triple broadcast_from(const double* p) { return broadcast(*p); }
  double lane0() const { return v[0]; }
  /// The x, y and z coordinates of three vectors: x = (p[0].x, p[1].x, p[2].x), ...
  static void transpose(const Vec3* p, Triple& x, Triple& y, Triple& z) {
    x = {{p[0].x, p[1].x, p[2].x}}, y = {{p[0].y, p[1].y, p[2].y}}, z = {{p[0].z, p[1].z, p[2].z}};
  }
  void store(double* p) const { p[0] = v[0], p[1] = v[1], p[2] = v[2]; }
  double operator[](int k) const { return v[k]; }
  Triple rotate1() const { return {{v[1], v[2], v[0]}}; }
  Triple rotate2() const { return {{v[2], v[0], v[1]}}; }
  static unsigned bits(M m) { return (m.m[0] ? 1u : 0u) | (m.m[1] ? 2u : 0u) | (m.m[2] ? 4u : 0u); }
};
template <class F>
inline Triple<Scalar> lanewise(const Triple<Scalar>& a, const Triple<Scalar>& b, F f) {
  return {{f(a.v[0], b.v[0]), f(a.v[1], b.v[1]), f(a.v[2], b.v[2])}};
}
inline Triple<Scalar> operator+(const Triple<Scalar>& a, const Triple<Scalar>& b) {
  return lanewise(a, b, [](double x, double y) { return x + y; });
}
inline Triple<Scalar> operator-(const Triple<Scalar>& a, const Triple<Scalar>& b) {
  return lanewise(a, b, [](double x, double y) { return x - y; });
}
inline Triple<Scalar> operator*(const Triple<Scalar>& a, const Triple<Scalar>& b) {
  return lanewise(a, b, [](double x, double y) { return x * y; });
}
inline Triple<Scalar> min(const Triple<Scalar>& a, const Triple<Scalar>& b) {
  return lanewise(a, b, [](double x, double y) { return Scalar::min({x}, {y}).v; });
}
inline Triple<Scalar> max(const Triple<Scalar>& a, const Triple<Scalar>& b) {
  return lanewise(a, b, [](double x, double y) { return Scalar::max({x}, {y}).v; });
}
inline Triple<Scalar> abs(const Triple<Scalar>& a) {
  return {{Scalar::abs({a.v[0]}).v, Scalar::abs({a.v[1]}).v, Scalar::abs({a.v[2]}).v}};
}
inline Triple<Scalar>::M operator>(const Triple<Scalar>& a, const Triple<Scalar>& b) {
  return {{a.v[0] > b.v[0], a.v[1] > b.v[1], a.v[2] > b.v[2]}};
}
inline Triple<Scalar>::M operator<=(const Triple<Scalar>& a, const Triple<Scalar>& b) {
  return {{a.v[0] <= b.v[0], a.v[1] <= b.v[1], a.v[2] <= b.v[2]}};
}
inline Triple<Scalar>::M operator|(const Triple<Scalar>::M& a, const Triple<Scalar>::M& b) {
  return {{a.m[0] || b.m[0], a.m[1] || b.m[1], a.m[2] || b.m[2]}};
}
inline Triple<Scalar>::M operator&(const Triple<Scalar>::M& a, const Triple<Scalar>::M& b) {
  return {{a.m[0] && b.m[0], a.m[1] && b.m[1], a.m[2] && b.m[2]}};
}

template <>
struct Triple<Avx2> {
  __m256d v;
  struct M {
    __m256d m;
  };
  [[gnu::target("avx2")]] static Triple set(double x, double y, double z) { return {_mm256_set_pd(0, z, y, x)}; }
  /// x, y, z (and nothing beyond them).
  [[gnu::target("avx2")]] static Triple load(const Vec3& p) {
    return {_mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(&p.x)), _mm_load_sd(&p.z), 1)};
  }
  [[gnu::target("avx2")]] static void transpose(const Triple& a, const Triple& b, const Triple& c, Triple* rows) {
    const __m256d xz01 = _mm256_unpacklo_pd(a.v, b.v), y01 = _mm256_unpackhi_pd(a.v, b.v);
    const __m256d xz22 = _mm256_unpacklo_pd(c.v, c.v), y22 = _mm256_unpackhi_pd(c.v, c.v);
    rows[0] = {_mm256_permute2f128_pd(xz01, xz22, 0x20)}, rows[1] = {_mm256_permute2f128_pd(y01, y22, 0x20)};
    rows[2] = {_mm256_permute2f128_pd(xz01, xz22, 0x31)};
  }
  [[gnu::target("avx2")]] static void transpose(const Vec3* p, Triple& x, Triple& y, Triple& z) {
    const __m256d c0 = load(p[0]).v, c1 = load(p[1]).v, c2 = load(p[2]).v;
    const __m256d xz01 = _mm256_unpacklo_pd(c0, c1), y01 = _mm256_unpackhi_pd(c0, c1);  // x0 x1 z0 z1, y0 y1 . .
    const __m256d xz22 = _mm256_unpacklo_pd(c2, c2), y22 = _mm256_unpackhi_pd(c2, c2);  // x2 x2 z2 z2, y2 y2 . .
    x = {_mm256_permute2f128_pd(xz01, xz22, 0x20)}, y = {_mm256_permute2f128_pd(y01, y22, 0x20)};
    z = {_mm256_permute2f128_pd(xz01, xz22, 0x31)};
  }
  [[gnu::target("avx2")]] static Triple broadcast(double x) { return {_mm256_set1_pd(x)}; }
  /// broadcast(*p), read from memory (one instruction).
  [[gnu::target("avx2")]] static Triple broadcast_from(const double* p) { return {_mm256_broadcast_sd(p)}; }
  [[gnu::target("avx2")]] double lane0() const { return _mm256_cvtsd_f64(v); }
  [[gnu::target("avx2")]] void store(double* p) const { _mm256_storeu_pd(p, v); }  // 4 doubles
  [[gnu::target("avx2")]] Triple rotate1() const { return {_mm256_permute4x64_pd(v, 0b11'00'10'01)}; }
  [[gnu::target("avx2")]] Triple rotate2() const { return {_mm256_permute4x64_pd(v, 0b11'01'00'10)}; }
  [[gnu::target("avx2")]] static unsigned bits(M m) { return static_cast<unsigned>(_mm256_movemask_pd(m.m)) & 7u; }
};
[[gnu::target("avx2")]] inline Triple<Avx2> operator+(Triple<Avx2> a, Triple<Avx2> b) { return {_mm256_add_pd(a.v, b.v)}; }
[[gnu::target("avx2")]] inline Triple<Avx2> operator-(Triple<Avx2> a, Triple<Avx2> b) { return {_mm256_sub_pd(a.v, b.v)}; }
[[gnu::target("avx2")]] inline Triple<Avx2> operator*(Triple<Avx2> a, Triple<Avx2> b) { return {_mm256_mul_pd(a.v, b.v)}; }
[[gnu::target("avx2")]] inline Triple<Avx2> min(Triple<Avx2> a, Triple<Avx2> b) { return {_mm256_min_pd(a.v, b.v)}; }
[[gnu::target("avx2")]] inline Triple<Avx2> max(Triple<Avx2> a, Triple<Avx2> b) { return {_mm256_max_pd(a.v, b.v)}; }
[[gnu::target("avx2")]] inline Triple<Avx2> abs(Triple<Avx2> a) { return {_mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v)}; }
[[gnu::target("avx2")]] inline Triple<Avx2>::M operator>(Triple<Avx2> a, Triple<Avx2> b) {
  return {_mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ)};
}
[[gnu::target("avx2")]] inline Triple<Avx2>::M operator<=(Triple<Avx2> a, Triple<Avx2> b) {
  return {_mm256_cmp_pd(a.v, b.v, _CMP_LE_OQ)};
}
[[gnu::target("avx2")]] inline Triple<Avx2>::M operator|(Triple<Avx2>::M a, Triple<Avx2>::M b) {
  return {_mm256_or_pd(a.m, b.m)};
}
[[gnu::target("avx2")]] inline Triple<Avx2>::M operator&(Triple<Avx2>::M a, Triple<Avx2>::M b) {
  return {_mm256_and_pd(a.m, b.m)};
}

}  // namespace cc::simd
