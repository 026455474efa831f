// Floating-point building blocks shared by the tests of the library.
//
// Two rules hold in every file of src/collide:
//  * Every sum of three terms goes through sum3(), whose result depends only on the multiset of
//    its terms, so permuting the axes, flipping an axis or swapping two shapes changes no rounding
//    (but the fast paths of the sphere, OBB and triangle tests sum left to right, in the bounds,
//    and so do the projection gaps, the boxes' features in the distance queries (box_features.h,
//    nearest_pair.h) and the triangle distance's choice of witnesses: a distance is judged on its
//    certified bound, not bit for bit under those symmetries).
//  * A test reports "disjoint" only when a separation exceeds a bound on the rounding error of
//    the quantities that show it (a certified separation). Tests are therefore conservative:
//    shapes that touch or overlap in exact arithmetic are never reported disjoint.
// The library is built with -ffp-contract=off: a fused multiply-add would change both.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace cc::fp {

/// Unit roundoff of IEEE-754 double precision with rounding to nearest.
inline constexpr double u = 0x1p-53;

/// Absolute slack added to error bounds for results that fall into the subnormal range, where
/// the relative error bound no longer holds. It covers a few dozen roundings of at most 2^-1075
/// each, each multiplied by a factor of at most 2^8.
inline constexpr double subnormal_slack = 0x1p-1058;

/// The median of three values, branch-free (three min/max operations).
inline double median3(double a, double b, double c) {
  return std::max(std::min(a, b), std::min(std::max(a, b), c));
}

/// a + b + c, rounded in a way that depends only on the multiset {a, b, c}: the median of the
/// three orders of summation. Hence sum3 is symmetric in its arguments, sum3(-a, -b, -c) ==
/// -sum3(a, b, c), and sum3(2^k a, 2^k b, 2^k c) == 2^k sum3(a, b, c) barring overflow and
/// underflow. Its error is that of any order: at most 2u(|a| + |b| + |c|) (plus underflow).
inline double sum3(double a, double b, double c) {
  return median3((a + b) + c, (a + c) + b, (b + c) + a);
}

/// x * 2^e: the value of std::ldexp(x, e) (both round once, correctly, on underflow and
/// overflow), as one multiplication when 2^e is a normal double (no library call).
inline double scale2(double x, int e) {
  if (e >= -1022 && e <= 1023) return x * std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
  return std::ldexp(x, e);
}

/// std::ilogb(m) for a finite m != 0, read from the exponent bits when m is normal.
inline int exponent_of(double m) {
  const int biased = static_cast<int>((std::bit_cast<std::uint64_t>(m) >> 52) & 0x7ff);
  return biased != 0 ? biased - 1023 : std::ilogb(m);
}

/// True when x is neither NaN nor infinite.
inline bool finite(double x) { return std::isfinite(x); }

}  // namespace cc::fp
