// Exact rational arithmetic (GMP) for the reference: every finite double is the rational it
// denotes, and sums, products and quotients of rationals are exact.
#pragma once

#include <gmpxx.h>

#include <string>

#include "collide/vec3.h"

namespace cc::exact {

using Rational = mpq_class;

/// The rational value of a finite double (exact).
Rational rational(double x);

/// The double nearest to a rational (ties to even); +-inf beyond the double range.
double to_double(const Rational& q);
/// The largest double <= q, and the smallest double >= q (-inf and +inf beyond the range).
double round_down(const Rational& q);
double round_up(const Rational& q);

struct QVec3 {
  Rational x, y, z;
  const Rational& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  Rational& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

QVec3 rational(const Vec3& v);
QVec3 operator+(const QVec3& a, const QVec3& b);
QVec3 operator-(const QVec3& a, const QVec3& b);
QVec3 operator*(const Rational& s, const QVec3& a);
Rational dot(const QVec3& a, const QVec3& b);
QVec3 cross(const QVec3& a, const QVec3& b);
bool is_zero(const QVec3& a);
/// A positive or negative number as m * 2^e, for magnitudes far outside the double range
/// (lengths of products of tiny or huge coordinates), used to normalise margins.
struct Magnitude {
  double m = 0;  // 0, or |m| in [1, 2)
  long e = 0;

  static Magnitude of(const Rational& q);  // rounded to double precision
  double to_double() const;                 // saturates to 0 or inf outside the double range
};
/// Magnitude::of(x 2^exponent) for an integer x: x rounded to 53 bits, to nearest, ties to even.
Magnitude nearest_magnitude(const mpz_class& x, long exponent);
Magnitude operator*(Magnitude a, Magnitude b);
Magnitude operator/(Magnitude a, Magnitude b);
/// a + b for a, b >= 0 (rounded).
Magnitude operator+(Magnitude a, Magnitude b);
/// The square root of a >= 0 (rounded).
Magnitude sqrt(Magnitude a);

/// Euclidean length (as a Magnitude, so it neither underflows nor overflows).
Magnitude length(const QVec3& a);
Vec3 to_double(const QVec3& a);

/// Largest |x| over finite doubles (0 for none).
double max_magnitude(std::initializer_list<double> values);

}  // namespace cc::exact
