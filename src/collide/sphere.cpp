#include "collide/sphere.h"

namespace cc {

bool test_sphere_sphere(const Sphere& a, const Sphere& b) {
  const Vec3 d = a.center - b.center;  // swapping a and b negates d exactly
  const double dist2 = fp::sum3(d.x * d.x, d.y * d.y, d.z * d.z);
  const double reach = a.radius + b.radius;
  const double reach2 = reach * reach;
  // Rounding error of dist2 - reach2: at most 5u dist2 (difference, square, sum3) plus
  // 3u reach2 (sum, square) plus u for the subtraction; 8u covers both with room for the
  // rounding of the bound itself. The slack covers squares that underflow.
  const double error = 8 * fp::u * (dist2 + reach2) + fp::subnormal_slack;
  if (!(dist2 - reach2 <= error)) return false;
  // On the hit path only: inputs outside the contract give false.
  return finite(a.center) && finite(b.center) && fp::finite(a.radius) && fp::finite(b.radius) &&
         a.radius >= 0 && b.radius >= 0;
}

}  // namespace cc
