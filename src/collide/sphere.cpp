#include "collide/sphere.h"

#include "collide/bound_records.h"

namespace cc {
namespace {

template <class Records>
bool test(const Sphere& a, const Sphere& b, Records& records) {
  Vec3 d = a.center - b.center;  // swapping a and b negates d exactly
  double reach = a.radius + b.radius;
  // Scaled by a power of two so that the largest of |d| and the reach lies in [1, 2): the squares
  // below neither underflow nor overflow, and the bound needs no absolute slack. (Exact, and the
  // same after permuting, flipping or scaling the inputs.)
  const double m = std::max(max_abs(d), std::fabs(reach));
  int e = 0;
  if (m > 0 && std::isfinite(m)) {
    e = fp::exponent_of(m);
    d = {fp::scale2(d.x, -e), fp::scale2(d.y, -e), fp::scale2(d.z, -e)};
    reach = fp::scale2(reach, -e);
  }
  const double dist2 = fp::sum3(d.x * d.x, d.y * d.y, d.z * d.z);
  const double reach2 = reach * reach;
  // The rounding error of dist2 - reach2 (see bounds::SphereBound). (A square that underflows
  // errs by 2^-1075, far below the bound.)
  const bounds::SphereBound bound{dist2, reach2};
  records.add(bounds::SphereSquares{a, b, e, bound});
  const double error = bound.total();
  if (!(dist2 - reach2 <= error)) return false;
  // On the hit path only: inputs outside the contract give false.
  return finite(a.center) && finite(b.center) && fp::finite(a.radius) && fp::finite(b.radius) &&
         a.radius >= 0 && b.radius >= 0;
}

}  // namespace

bool test_sphere_sphere(const Sphere& a, const Sphere& b) {
  bounds::NoRecords none;
  return test(a, b, none);
}

bool test_sphere_sphere(const Sphere& a, const Sphere& b, bounds::Records& records) { return test(a, b, records); }

}  // namespace cc
