// The bound of test_sphere_sphere (sphere.h), and its record.
#pragma once

#include "collide/fp.h"
#include "collide/record_sink.h"
#include "collide/sphere.h"

namespace cc::bounds {

/// dist2 - reach2 (the squared offset and the squared sum of the radii, both scaled to [1, 4))
/// is certified against total().
struct SphereBound {
  double dist2, reach2;  // as computed
  /// The difference, the squares and their sum (in any order) make dist2 within 5u of its value,
  /// the subtraction adds u of it: 8u leaves room for the bound's own rounding.
  double distance() const { return 8 * fp::u * dist2; }
  /// The sum and the square make reach2 within 3u.
  double reach() const { return 8 * fp::u * reach2; }
  double total() const { return distance() + reach(); }
};

/// The offset and the reach scaled by 2^-exponent, squared.
struct SphereSquares {
  Sphere a, b;
  int exponent = 0;
  SphereBound bound;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (sphere.h), recording its certified quantities into `records`
/// (bound_records.h); the same answer, bit for bit.
bool test_sphere_sphere(const Sphere& a, const Sphere& b, bounds::Records& records);

}  // namespace cc
