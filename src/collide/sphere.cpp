#include "collide/sphere.h"

#include "collide/record_sink.h"
#include "collide/sphere_bound.h"

namespace cc {
namespace {

// The decision once dist2 and reach2 are computed: dist2 - reach2 within its rounding error
// (bounds::SphereBound); true then for inputs in the contract (checked by the caller).
template <class Records>
bool within_reach(const Sphere& a, const Sphere& b, int exponent, double dist2, double reach2, Records& records) {
  const bounds::SphereBound bound{dist2, reach2};
  records.add(bounds::SphereSquares{a, b, exponent, bound});
  return dist2 - reach2 <= bound.total();
}

// Scaled by a power of two so that the largest of |d| and the reach lies in [1, 2): the squares
// below neither underflow nor overflow, and the bound needs no absolute slack. (Exact: the scaled
// values are the given ones times 2^-e.) Out of line: the rare path. The squares are summed left
// to right, as in test(): swapping the spheres, flipping an axis or scaling by a power of two
// changes no rounding; permuting the axes changes the order, within the bound.
template <class Records>
[[gnu::noinline]] bool test_scaled(const Sphere& a, const Sphere& b, Records& records) {
  Vec3 d = a.center - b.center;
  double reach = a.radius + b.radius;
  const double m = std::max(max_abs(d), std::fabs(reach));
  int e = 0;
  if (m > 0 && std::isfinite(m)) {
    e = fp::exponent_of(m);
    d = {fp::scale2(d.x, -e), fp::scale2(d.y, -e), fp::scale2(d.z, -e)};
    reach = fp::scale2(reach, -e);
  }
  // The rounding error of dist2 - reach2 (see bounds::SphereBound). (A square that underflows
  // errs by 2^-1075, far below the bound.)
  if (!within_reach(a, b, e, d.x * d.x + d.y * d.y + d.z * d.z, reach * reach, records)) return false;
  // On the hit path only: inputs outside the contract give false.
  return finite(a.center) && finite(b.center) && fp::finite(a.radius) && fp::finite(b.radius) && a.radius >= 0 &&
         b.radius >= 0;
}

template <class Records>
bool test(const Sphere& a, const Sphere& b, Records& records) {
  const Vec3 d = a.center - b.center;  // swapping a and b negates d exactly
  const double reach = a.radius + b.radius;
  // As given, when the squares' sum lies in [2^-900, 2^1020]: then nothing that matters has
  // overflowed or underflowed (a square below 2^-1022 is below half an ulp of the larger terms,
  // whatever it rounds to), so these are the scaled test's values times 4^e exactly, and both
  // bounds' slack lies below half an ulp of the rest: the same decision, without scaling. (NaN
  // and overflow fail the range test and take the scaled path.)
  const double dist2 = d.x * d.x + d.y * d.y + d.z * d.z, reach2 = reach * reach;
  const double sum = dist2 + reach2;
  if (!(sum >= 0x1p-900 && sum <= 0x1p1020)) return test_scaled(a, b, records);
  // In that range the squares are finite, so are both centres and both radii (an infinite
  // coordinate or radius makes a square infinite, or NaN): the contract is the radii's signs.
  return within_reach(a, b, 0, dist2, reach2, records) && a.radius >= 0 && b.radius >= 0;
}

}  // namespace

bool test_sphere_sphere(const Sphere& a, const Sphere& b) {
  bounds::NoRecords none;
  return test(a, b, none);
}

bool test_sphere_sphere(const Sphere& a, const Sphere& b, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return test(a, b, into);
}

}  // namespace cc
