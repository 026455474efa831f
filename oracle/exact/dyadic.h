// Dyadic rationals as integers on a power of two: every double is m 2^e with an integer m, so
// sums and products of doubles are integers on a common power of two, computed by GMP without
// a gcd. The roundings here are the ones rational.h takes on the same values (its
// nearest_magnitude rounds such an integer as Magnitude::of rounds the rational).
#pragma once

#include <gmpxx.h>

#include <array>

#include "collide/vec3.h"

#include "oracle/exact/rational.h"

namespace cc::exact {

/// The binary exponent of the last bit of a finite nonzero double: x = m 2^e with an odd m.
long lowest_exponent(double x);
/// The least of `bound` and the last bits' exponents of v's nonzero coordinates: every
/// coordinate of v is an integer on 2^result.
long lowest_exponent(const Vec3& v, long bound);

/// out = x / 2^exponent, an integer: requires x finite and exponent <= lowest_exponent(x) (or
/// x == 0).
void set_on(mpz_class& out, double x, long exponent);

/// A vector of integers, all on one power of two.
using IntVec3 = std::array<mpz_class, 3>;

/// v's coordinates on 2^exponent (each as set_on).
IntVec3 on_grid(const Vec3& v, long exponent);
/// out = u x v, and out = u . v, in integers (out must not be u or v).
void cross(IntVec3& out, const IntVec3& u, const IntVec3& v);
void dot(mpz_class& out, const IntVec3& u, const IntVec3& v);
bool is_zero(const IntVec3& v);

/// x 2^exponent as a rational.
Rational rational_on(const mpz_class& x, long exponent);

/// exact::length of a vector whose squared norm is square 2^(2 exponent): the square rounded to
/// a double, then its square root rounded (an even power of two taken out of the square
/// changes neither rounding).
Magnitude length_from_square(const mpz_class& square, long exponent);

}  // namespace cc::exact
