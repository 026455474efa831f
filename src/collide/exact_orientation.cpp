// orientation_sign and planar_orientation_sign: a floating-point filter, then integers.
//
// The filter evaluates the determinant in doubles and returns its sign when its magnitude exceeds
// a bound on the rounding error (derivations at the bounds below). Otherwise each coordinate,
// m * 2^e with m an odd integer, is scaled by 2^-emin (emin: the least e over the nonzero
// coordinates involved) to an integer below 2^W, W = max(e + bit width of m) - emin, and the
// determinant is evaluated exactly in two's complement integers of N 64-bit limbs, N chosen from
// W so that no intermediate value can overflow. Finite doubles have W <= 1024 + 1074 = 2098, so
// N = 99 limbs decides every finite input. Usual inputs take far fewer: 4 limbs when W <= 83
// (e.g. coordinates of up to 53 bits whose magnitudes lie within 2^30 of each other), 16 when
// W <= 339 (magnitudes within 2^286 of each other).
#include "collide/exact_orientation.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace cc {
namespace {

// ---- The filter --------------------------------------------------------------------------------
//
// Model (round to nearest, no fused multiply-add: the library is built with -ffp-contract=off):
// a sum or difference of doubles is (x +- y)(1 + d) with |d| <= u = 2^-53, also when the result is
// subnormal (then it is exact); a product is xy(1 + d) + h with |d| <= u, |h| <= 2^-1075 (h for
// underflow). Overflow is excluded below.
//
// 3-D. With the rounded differences x_i = (d - a)_i and the minors m_i = fl(fl(p_i) - fl(p'_i)),
// p_i, p'_i the two products of component i of (b - a) x (c - a), the filter computes
// det = fl(fl(fl(x_0 m_0) + fl(x_1 m_1)) + fl(x_2 m_2)). Let S be that last sum before its rounding:
// det = S(1 + d), so det and S have the same sign and |S| >= |det| / (1 + u). Let P be the exact
// permanent of the rounded differences, sum_i |x_i| (|p_i| + |p'_i|) on exact products, and
// X = sum_i |x_i|.
//  * The exact determinant D of the points differs from the exact determinant D' of the rounded
//    differences by at most gamma_3 P (each of its six terms is a product of three differences,
//    each rounded once; gamma_k = ku / (1 - ku)).
//  * Following the roundings: |S - D'| <= (4u + 6u^2 + 4u^3 + u^4) P + 2(1 + u)^3 2^-1075 X
//    + (3 + 2u) 2^-1075 (two products, one difference and one product in each term, one sum for
//    the first two terms; the underflow of the products of the minors is multiplied by x_i).
//  So |S - D| <= (7u + 16u^2) P + 2.01 2^-1075 X + 3.01 2^-1075.
//  * The permanent computed in doubles, Pc (the same operations on absolute values, five
//    roundings of nonnegative terms), has Pc >= (1 - u)^5 P - 2^-1074 X - 3 2^-1075.
//  * bound = fl(fl(c Pc) + fl(2^-1020 fl(1 + Xc))), Xc = X summed in doubles, is at least
//    (1 - u)^2 c Pc - 2^-1075 + (1 - u)^4 2^-1020 (1 + X).
//  The sign of det is that of D when |det| > bound, i.e. when bound / (1 + u) >= |S - D|. That
//  holds for c >= (7u + 16u^2)(1 + u) / (1 - u)^7 = 7u + 72u^2 + O(u^3), taken as c = (7 + 128u)u,
//  the absolute term 2^-1020 (1 + X) covering the 2^-1075 terms many times over. (Shewchuk's
//  orient3d bound (7 + 56u)u has the same first-order term.) Overflow anywhere makes Pc infinite
//  or NaN (each intermediate of the permanent is at least the magnitude of the corresponding one
//  of det, the operations being monotone), so is the bound, and neither comparison holds; NaN
//  inputs likewise.
constexpr double kOrientation3Bound = (7 + 128 * fp::u) * fp::u;
//
// 2-D. det = fl(fl(x y) - fl(x' y')) on rounded differences x, y, x', y'; S = the difference
// before rounding. |D - D'| <= gamma_2 P, P = |x y| + |x' y'|; |S - D'| <= u P + 2 2^-1075. So
// |S - D| <= (3u + 5u^2) P + 2^-1074. Pc = fl(|fl(x y)| + |fl(x' y')|) >= (1 - u)^2 P - 2^-1074,
// bound = fl(fl(c Pc) + 2^-1020) >= (1 - u)((1 - u) c Pc - 2^-1075 + 2^-1020): enough for
// c >= (3u + 5u^2)(1 + u) / (1 - u)^4 = 3u + 20u^2 + O(u^3), taken as c = (3 + 32u)u.
constexpr double kOrientation2Bound = (3 + 32 * fp::u) * fp::u;
// The absolute part of both bounds (a normal number, so that 2^-1020 (1 + Xc) is exact).
constexpr double kUnderflowSlack = 0x1p-1020;

std::optional<int> filter_sign(double det, double bound) {
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return std::nullopt;
}

// ---- Exact integers ----------------------------------------------------------------------------

__extension__ typedef unsigned __int128 U128;

constexpr int kLimbBits = 64;
// The widest finite inputs have W = 2098 (see the top of the file) and need 3W + 7 bits (see
// exact_sign_3d).
constexpr std::size_t kMaxLimbs = (3 * 2098 + 7 + kLimbBits - 1) / kLimbBits;
static_assert(kMaxLimbs == 99);

// A two's complement integer of N 64-bit limbs, least significant first. The arithmetic is modulo
// 2^(64N), hence exact whenever the true result fits.
template <std::size_t N>
using Wide = std::array<std::uint64_t, N>;

// A finite double as (-1)^negative m 2^e, m odd, or m = 0 for zero.
struct Dyadic {
  std::uint64_t m = 0;
  int e = 0;
  bool negative = false;
};

Dyadic dyadic(double x) {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t m = bits & ((std::uint64_t{1} << 52) - 1);
  int e = -1074;
  if (biased != 0) m |= std::uint64_t{1} << 52, e = biased - 1075;
  if (m == 0) return {};
  const int zeros = std::countr_zero(m);
  return {m >> zeros, e + zeros, (bits >> 63) != 0};
}

// The scaling of a set of coordinates: the least exponent and the width W of the scaled integers
// (each scaled coordinate is below 2^W in magnitude). W = -1 when all are zero.
struct Scale {
  int emin = 0;
  int width = -1;
};

template <std::size_t K>
Scale common_scale(const std::array<Dyadic, K>& v) {
  int lo = 0, hi = 0;
  bool any = false;
  for (const Dyadic& x : v) {
    if (x.m == 0) continue;
    const int top = x.e + static_cast<int>(std::bit_width(x.m));
    lo = any ? std::min(lo, x.e) : x.e;
    hi = any ? std::max(hi, top) : top;
    any = true;
  }
  return any ? Scale{lo, hi - lo} : Scale{};
}

// x 2^-emin as an integer (64N bits exceed the width W, so it fits with its sign).
template <std::size_t N>
Wide<N> to_wide(const Dyadic& x, int emin) {
  Wide<N> r{};
  if (x.m == 0) return r;
  const int shift = x.e - emin;
  const auto limb = static_cast<std::size_t>(shift / kLimbBits);
  const int bit = shift % kLimbBits;
  const U128 v = static_cast<U128>(x.m) << bit;
  r[limb] = static_cast<std::uint64_t>(v);
  if (limb + 1 < N) r[limb + 1] = static_cast<std::uint64_t>(v >> kLimbBits);
  if (x.negative) {  // two's complement: invert and add one
    std::uint64_t carry = 1;
    for (std::uint64_t& w : r) {
      w = ~w + carry;
      carry = (carry != 0 && w == 0) ? 1 : 0;
    }
  }
  return r;
}

template <std::size_t N>
Wide<N> operator-(const Wide<N>& a, const Wide<N>& b) {
  Wide<N> r;
  std::uint64_t borrow = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const U128 v = static_cast<U128>(a[i]) - b[i] - borrow;
    r[i] = static_cast<std::uint64_t>(v);
    borrow = static_cast<std::uint64_t>(v >> 127);
  }
  return r;
}

template <std::size_t N>
Wide<N> operator+(const Wide<N>& a, const Wide<N>& b) {
  Wide<N> r;
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const U128 v = static_cast<U128>(a[i]) + b[i] + carry;
    r[i] = static_cast<std::uint64_t>(v);
    carry = static_cast<std::uint64_t>(v >> kLimbBits);
  }
  return r;
}

// The low N limbs of the product: the two's complement product whenever it fits.
template <std::size_t N>
Wide<N> operator*(const Wide<N>& a, const Wide<N>& b) {
  Wide<N> r{};
  for (std::size_t i = 0; i < N; ++i) {
    if (a[i] == 0) continue;
    std::uint64_t carry = 0;
    for (std::size_t j = 0; i + j < N; ++j) {
      const U128 v = static_cast<U128>(a[i]) * b[j] + r[i + j] + carry;
      r[i + j] = static_cast<std::uint64_t>(v);
      carry = static_cast<std::uint64_t>(v >> kLimbBits);
    }
  }
  return r;
}

template <std::size_t N>
int sign_of(const Wide<N>& x) {
  if ((x[N - 1] >> 63) != 0) return -1;
  for (std::uint64_t w : x) {
    if (w != 0) return 1;
  }
  return 0;
}

// The 3-D determinant on v = a, b, c, d (coordinates x, y, z of each) scaled by 2^-emin, whose
// width W satisfies 3W + 7 <= 64N: scaled coordinates are below 2^W, differences below 2^(W+1),
// products of two below 2^(2W+2), minors below 2^(2W+3), their products with a difference below
// 2^(3W+4), the sum of three below 2^(3W+6), so 3W + 7 bits hold every value with its sign.
template <std::size_t N>
int exact_sign_3d(const std::array<Dyadic, 12>& v, int emin) {
  std::array<Wide<N>, 12> w;
  for (std::size_t k = 0; k < 12; ++k) w[k] = to_wide<N>(v[k], emin);
  const Wide<N> bx = w[3] - w[0], by = w[4] - w[1], bz = w[5] - w[2];
  const Wide<N> cx = w[6] - w[0], cy = w[7] - w[1], cz = w[8] - w[2];
  const Wide<N> dx = w[9] - w[0], dy = w[10] - w[1], dz = w[11] - w[2];
  return sign_of<N>(dx * (by * cz - bz * cy) + dy * (bz * cx - bx * cz) + dz * (bx * cy - by * cx));
}

// The 2-D determinant on v = a, b, c (the two kept coordinates of each), 2W + 4 <= 64N:
// differences below 2^(W+1), products below 2^(2W+2), their difference below 2^(2W+3).
template <std::size_t N>
int exact_sign_2d(const std::array<Dyadic, 6>& v, int emin) {
  std::array<Wide<N>, 6> w;
  for (std::size_t k = 0; k < 6; ++k) w[k] = to_wide<N>(v[k], emin);
  return sign_of<N>((w[2] - w[0]) * (w[5] - w[1]) - (w[3] - w[1]) * (w[4] - w[0]));
}

// f.template operator()<N>() for the least N of a few sizes with 64N >= bits (bits <= 64 kMaxLimbs):
// small sizes for the usual inputs, whose loops the compiler unrolls.
template <typename F>
int with_limbs_for(int bits, F&& f) {
  if (bits <= 2 * kLimbBits) return f.template operator()<2>();
  if (bits <= 3 * kLimbBits) return f.template operator()<3>();
  if (bits <= 4 * kLimbBits) return f.template operator()<4>();
  if (bits <= 6 * kLimbBits) return f.template operator()<6>();
  if (bits <= 8 * kLimbBits) return f.template operator()<8>();
  if (bits <= 16 * kLimbBits) return f.template operator()<16>();
  if (bits <= 32 * kLimbBits) return f.template operator()<32>();
  return f.template operator()<kMaxLimbs>();
}

bool all_finite(const Vec3& a, const Vec3& b, const Vec3& c) { return finite(a) && finite(b) && finite(c); }

// The axes kept by a projection: (drop + 1) % 3 and (drop + 2) % 3, so that the 2-D determinant
// is component `drop` of the cross product.
constexpr int kFirstKept[3] = {1, 2, 0}, kSecondKept[3] = {2, 0, 1};

}  // namespace

namespace orientation_stages {

std::optional<int> filtered_orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double bx = b.x - a.x, by = b.y - a.y, bz = b.z - a.z;
  const double cx = c.x - a.x, cy = c.y - a.y, cz = c.z - a.z;
  const double dx = d.x - a.x, dy = d.y - a.y, dz = d.z - a.z;
  const double p0 = by * cz, q0 = bz * cy, p1 = bz * cx, q1 = bx * cz, p2 = bx * cy, q2 = by * cx;
  const double det = (dx * (p0 - q0) + dy * (p1 - q1)) + dz * (p2 - q2);
  const double adx = std::fabs(dx), ady = std::fabs(dy), adz = std::fabs(dz);
  const double permanent = (adx * (std::fabs(p0) + std::fabs(q0)) + ady * (std::fabs(p1) + std::fabs(q1))) +
                           adz * (std::fabs(p2) + std::fabs(q2));
  const double bound = kOrientation3Bound * permanent + kUnderflowSlack * (1 + ((adx + ady) + adz));
  return filter_sign(det, bound);
}

std::optional<int> filtered_planar_orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, int drop) {
  if (drop < 0 || drop > 2) return std::nullopt;
  const int i = kFirstKept[drop], j = kSecondKept[drop];
  const double p = (b[i] - a[i]) * (c[j] - a[j]), q = (b[j] - a[j]) * (c[i] - a[i]);
  const double bound = kOrientation2Bound * (std::fabs(p) + std::fabs(q)) + kUnderflowSlack;
  return filter_sign(p - q, bound);
}

std::optional<int> exact_orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (!all_finite(a, b, c) || !finite(d)) return std::nullopt;
  const std::array<Dyadic, 12> v = {dyadic(a.x), dyadic(a.y), dyadic(a.z), dyadic(b.x), dyadic(b.y), dyadic(b.z),
                                    dyadic(c.x), dyadic(c.y), dyadic(c.z), dyadic(d.x), dyadic(d.y), dyadic(d.z)};
  const Scale s = common_scale(v);
  if (s.width < 0) return 0;
  return with_limbs_for(3 * s.width + 7, [&]<std::size_t N>() { return exact_sign_3d<N>(v, s.emin); });
}

std::optional<int> exact_planar_orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, int drop) {
  if (drop < 0 || drop > 2) return std::nullopt;
  const int i = kFirstKept[drop], j = kSecondKept[drop];
  const Vec3 ka{a[i], a[j], 0}, kb{b[i], b[j], 0}, kc{c[i], c[j], 0};
  if (!all_finite(ka, kb, kc)) return std::nullopt;
  const std::array<Dyadic, 6> v = {dyadic(ka.x), dyadic(ka.y), dyadic(kb.x), dyadic(kb.y), dyadic(kc.x), dyadic(kc.y)};
  const Scale s = common_scale(v);
  if (s.width < 0) return 0;
  return with_limbs_for(2 * s.width + 4, [&]<std::size_t N>() { return exact_sign_2d<N>(v, s.emin); });
}

}  // namespace orientation_stages

std::optional<int> orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (const std::optional<int> s = orientation_stages::filtered_orientation_sign(a, b, c, d)) return s;
  return orientation_stages::exact_orientation_sign(a, b, c, d);
}

std::optional<int> planar_orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, int drop) {
  if (const std::optional<int> s = orientation_stages::filtered_planar_orientation_sign(a, b, c, drop)) return s;
  return orientation_stages::exact_planar_orientation_sign(a, b, c, drop);
}

}  // namespace cc
