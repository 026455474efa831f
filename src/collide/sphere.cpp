#include "collide/sphere.h"

namespace cc {

bool test_sphere_sphere(const Sphere& a, const Sphere& b) {
  Vec3 d = a.center - b.center;  // swapping a and b negates d exactly
  double reach = a.radius + b.radius;
  // Scaled by a power of two so that the largest of |d| and the reach lies in [1, 2): the squares
  // below neither underflow nor overflow, and the bound needs no absolute slack. (Exact, and the
  // same after permuting, flipping or scaling the inputs.)
  const double m = std::max(max_abs(d), std::fabs(reach));
  if (m > 0 && std::isfinite(m)) {
    const int e = fp::exponent_of(m);
    d = {fp::scale2(d.x, -e), fp::scale2(d.y, -e), fp::scale2(d.z, -e)};
    reach = fp::scale2(reach, -e);
  }
  const double dist2 = fp::sum3(d.x * d.x, d.y * d.y, d.z * d.z);
  const double reach2 = reach * reach;
  // Rounding error of dist2 - reach2: at most 5u dist2 (difference, square, sum3) plus
  // 3u reach2 (sum, square) plus u for the subtraction; 8u covers both with room for the
  // rounding of the bound itself. (A square that underflows errs by 2^-1075, far below 8u.)
  const double error = 8 * fp::u * (dist2 + reach2);
  if (!(dist2 - reach2 <= error)) return false;
  // On the hit path only: inputs outside the contract give false.
  return finite(a.center) && finite(b.center) && fp::finite(a.radius) && fp::finite(b.radius) &&
         a.radius >= 0 && b.radius >= 0;
}

}  // namespace cc
