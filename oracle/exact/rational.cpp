#include "oracle/exact/rational.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cc::exact {

Rational rational(double x) {
  if (!std::isfinite(x)) throw std::invalid_argument("rational(): not a finite double");
  Rational q;
  mpq_set_d(q.get_mpq_t(), x);  // exact for every finite double
  return q;
}

namespace {

// Whether q's denominator is a power of two, 2^shift (so q is an integer times 2^-shift): every
// sum and product of doubles is such a rational.
bool dyadic(const Rational& q, unsigned long& shift) {
  const mpz_srcptr den = q.get_den_mpz_t();
  const std::size_t bits = mpz_sizeinbase(den, 2);
  if (mpz_scan1(den, 0) != bits - 1) return false;
  shift = static_cast<unsigned long>(bits - 1);
  return true;
}

}  // namespace

double to_double(const Rational& q) {
  // A dyadic rational whose rounding lands among the normal doubles: its numerator rounded to
  // 53 bits is the nearest double.
  if (unsigned long shift = 0; dyadic(q, shift)) {
    const Magnitude m = nearest_magnitude(q.get_num(), -static_cast<long>(shift));
    if (m.m == 0) return 0;
    if (m.e >= -1022 && m.e <= 1023) return std::ldexp(m.m, static_cast<int>(m.e));
  }
  // mpq_get_d truncates; round to nearest by comparing with the two neighbours.
  const double t = mpq_get_d(q.get_mpq_t());
  if (!std::isfinite(t)) return t;
  const double up = std::nextafter(t, q > 0 ? INFINITY : -INFINITY);
  if (!std::isfinite(up)) {
    // Past the largest double: IEEE rounds to infinity from half an ulp beyond it on (the tie
    // too: DBL_MAX's significand is odd), as if the next double were 2^1024.
    const Rational half_ulp = abs(rational(t) - rational(std::nextafter(t, 0.0))) / 2;
    return abs(q - rational(t)) >= half_ulp ? up : t;
  }
  const Rational dt = abs(q - rational(t)), du = abs(rational(up) - q);
  if (du < dt) return up;
  if (du == dt) {  // a tie: to the even significand
    std::uint64_t bits = 0;
    std::memcpy(&bits, &t, sizeof bits);
    return (bits & 1) ? up : t;
  }
  return t;
}

double round_down(const Rational& q) {
  double x = to_double(q);
  if (x == INFINITY) return std::numeric_limits<double>::max();
  if (x != -INFINITY && rational(x) > q) x = std::nextafter(x, -INFINITY);
  return x;
}

double round_up(const Rational& q) {
  double x = to_double(q);
  if (x == -INFINITY) return -std::numeric_limits<double>::max();
  if (x != INFINITY && rational(x) < q) x = std::nextafter(x, INFINITY);
  return x;
}

QVec3 rational(const Vec3& v) { return {rational(v.x), rational(v.y), rational(v.z)}; }
QVec3 operator+(const QVec3& a, const QVec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
QVec3 operator-(const QVec3& a, const QVec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
QVec3 operator*(const Rational& s, const QVec3& a) { return {s * a.x, s * a.y, s * a.z}; }
Rational dot(const QVec3& a, const QVec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
QVec3 cross(const QVec3& a, const QVec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
bool is_zero(const QVec3& a) { return sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0; }
namespace {

// floor(log2(|q|)) up to one (from the bit lengths), for q != 0.
long rough_log2(const Rational& q) {
  return static_cast<long>(mpz_sizeinbase(q.get_num_mpz_t(), 2)) -
         static_cast<long>(mpz_sizeinbase(q.get_den_mpz_t(), 2));
}

// q * 2^-e, exactly.
Rational scaled(const Rational& q, long e) {
  Rational r;
  if (e >= 0) {
    mpq_div_2exp(r.get_mpq_t(), q.get_mpq_t(), static_cast<unsigned long>(e));
  } else {
    mpq_mul_2exp(r.get_mpq_t(), q.get_mpq_t(), static_cast<unsigned long>(-e));
  }
  return r;
}

Magnitude normalised(double m, long e) {
  if (m == 0 || !std::isfinite(m)) return {m, 0};
  int k = 0;
  const double f = std::frexp(m, &k);  // m = f 2^k, |f| in [0.5, 1)
  return {2 * f, e + k - 1};
}

}  // namespace

Magnitude nearest_magnitude(const mpz_class& x, long exponent) {
  const int sign = sgn(x);
  if (sign == 0) return {};
  const std::size_t bits = mpz_sizeinbase(x.get_mpz_t(), 2);
  if (bits <= 53) return normalised(mpz_get_d(x.get_mpz_t()), exponent);
  const std::size_t shift = bits - 53;
  thread_local mpz_class top;
  mpz_abs(top.get_mpz_t(), x.get_mpz_t());
  const bool half = mpz_tstbit(top.get_mpz_t(), shift - 1) != 0;
  const bool beyond_half = mpz_scan1(top.get_mpz_t(), 0) < shift - 1;
  mpz_tdiv_q_2exp(top.get_mpz_t(), top.get_mpz_t(), shift);
  unsigned long q = mpz_get_ui(top.get_mpz_t());
  if (half && (beyond_half || (q & 1))) ++q;  // 2^53 at most: exact in a double
  return normalised(sign * static_cast<double>(q), exponent + static_cast<long>(shift));
}

Magnitude Magnitude::of(const Rational& q) {
  if (sgn(q) == 0) return {};
  if (unsigned long shift = 0; dyadic(q, shift)) return nearest_magnitude(q.get_num(), -static_cast<long>(shift));
  const long e = rough_log2(q);
  return normalised(exact::to_double(scaled(q, e)), e);
}

double Magnitude::to_double() const {
  if (m == 0) return 0;
  if (e > 2000) return std::copysign(INFINITY, m);
  if (e < -2000) return std::copysign(0.0, m);
  return std::ldexp(m, static_cast<int>(e));
}

Magnitude operator*(Magnitude a, Magnitude b) { return normalised(a.m * b.m, a.e + b.e); }
Magnitude operator/(Magnitude a, Magnitude b) { return normalised(a.m / b.m, a.e - b.e); }

Magnitude operator+(Magnitude a, Magnitude b) {
  if (a.m == 0) return b;
  if (b.m == 0) return a;
  const long e = std::max(a.e, b.e);
  return normalised(std::ldexp(a.m, static_cast<int>(std::max(a.e - e, -2000L))) +
                        std::ldexp(b.m, static_cast<int>(std::max(b.e - e, -2000L))),
                    e);
}

Magnitude sqrt(Magnitude a) {
  if (a.m == 0) return a;
  if (a.e % 2 != 0) a.m *= 2, a.e -= 1;
  return normalised(std::sqrt(a.m), a.e / 2);
}

Magnitude length(const QVec3& a) {
  long e = std::numeric_limits<long>::min();
  for (int i = 0; i < 3; ++i) {
    if (sgn(a[i]) != 0) e = std::max(e, rough_log2(a[i]));
  }
  if (e == std::numeric_limits<long>::min()) return {};
  const QVec3 b{scaled(a.x, e), scaled(a.y, e), scaled(a.z, e)};
  return normalised(std::sqrt(to_double(dot(b, b))), e);
}

Vec3 to_double(const QVec3& a) { return {to_double(a.x), to_double(a.y), to_double(a.z)}; }

double max_magnitude(std::initializer_list<double> values) {
  double m = 0;
  for (double v : values) {
    if (std::isfinite(v)) m = std::max(m, std::fabs(v));
  }
  return m;
}

}  // namespace cc::exact
