#include "oracle/exact/dyadic.h"

#include <algorithm>
#include <cmath>

namespace cc::exact {
namespace {

// x = odd 2^exponent, for a finite nonzero x.
void split(double x, long long& odd, long& exponent) {
  int k = 0;
  const double f = std::frexp(x, &k);
  const auto m = static_cast<long long>(std::ldexp(f, 53));  // x = m 2^(k - 53), 0 < |m| < 2^53
  const int zeros = __builtin_ctzll(static_cast<unsigned long long>(m));
  odd = m >> zeros;  // exact: the bits shifted out are zeros
  exponent = k - 53 + zeros;
}

}  // namespace

long lowest_exponent(double x) {
  long long odd = 0;
  long exponent = 0;
  split(x, odd, exponent);
  return exponent;
}

long lowest_exponent(const Vec3& v, long bound) {
  for (int k = 0; k < 3; ++k) {
    if (v[k] != 0) bound = std::min(bound, lowest_exponent(v[k]));
  }
  return bound;
}

void set_on(mpz_class& out, double x, long exponent) {
  if (x == 0) {
    out = 0;
    return;
  }
  long long odd = 0;
  long e = 0;
  split(x, odd, e);
  mpz_set_si(out.get_mpz_t(), static_cast<long>(odd));
  mpz_mul_2exp(out.get_mpz_t(), out.get_mpz_t(), static_cast<unsigned long>(e - exponent));
}

IntVec3 on_grid(const Vec3& v, long exponent) {
  IntVec3 out;
  for (int k = 0; k < 3; ++k) set_on(out[k], v[k], exponent);
  return out;
}

void cross(IntVec3& out, const IntVec3& u, const IntVec3& v) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    mpz_mul(out[i].get_mpz_t(), u[j].get_mpz_t(), v[k].get_mpz_t());
    mpz_submul(out[i].get_mpz_t(), u[k].get_mpz_t(), v[j].get_mpz_t());
  }
}

void dot(mpz_class& out, const IntVec3& u, const IntVec3& v) {
  mpz_mul(out.get_mpz_t(), u[0].get_mpz_t(), v[0].get_mpz_t());
  mpz_addmul(out.get_mpz_t(), u[1].get_mpz_t(), v[1].get_mpz_t());
  mpz_addmul(out.get_mpz_t(), u[2].get_mpz_t(), v[2].get_mpz_t());
}

bool is_zero(const IntVec3& v) { return sgn(v[0]) == 0 && sgn(v[1]) == 0 && sgn(v[2]) == 0; }

Rational rational_on(const mpz_class& x, long exponent) {
  Rational q{x};
  if (exponent >= 0) {
    mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<unsigned long>(exponent));
  } else {
    mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<unsigned long>(-exponent));
  }
  return q;
}

Magnitude length_from_square(const mpz_class& square, long exponent) {
  return sqrt(nearest_magnitude(square, 2 * exponent));
}

}  // namespace cc::exact
