#include "oracle/exact/exact_kdops.h"

#include <array>
#include <cmath>
#include <cstdlib>

#include "collide/kdop.h"
#include "oracle/exact/dyadic.h"

namespace cc::exact {

// On integers: every coordinate of both sets on one power of two 2^L (dyadic.h), so that a
// projection onto a direction of components 0 and +-1 is a sum and difference of integers; the
// slab's ends and overlap become rationals at the end.
std::vector<ExactSlab> exact_kdop_slabs(int k, const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  long lowest = 0;
  for (const auto* set : {&a, &b}) {
    for (const Vec3& p : *set) lowest = lowest_exponent(p, lowest);
  }
  const auto placed = [lowest](const std::vector<Vec3>& points) {
    std::vector<IntVec3> out;
    for (const Vec3& p : points) out.push_back(on_grid(p, lowest));
    return out;
  };
  const std::vector<IntVec3> ia = placed(a), ib = placed(b);
  std::vector<ExactSlab> slabs;
  mpz_class s, a_lo, a_hi, b_lo, b_hi, overlap;
  for (const KdopDirection& dir : kdop_directions(k)) {
    const std::array<int, 3> d{dir.x, dir.y, dir.z};
    const auto extent = [&d, &s](const std::vector<IntVec3>& points, mpz_class& lo, mpz_class& hi) {
      for (std::size_t j = 0; j < points.size(); ++j) {
        s = 0;
        for (int i = 0; i < 3; ++i) {
          if (d[i] > 0) s += points[j][i];
          if (d[i] < 0) s -= points[j][i];
        }
        if (j == 0 || s < lo) lo = s;
        if (j == 0 || s > hi) hi = s;
      }
    };
    extent(ia, a_lo, a_hi);
    extent(ib, b_lo, b_hi);
    overlap = (a_hi < b_hi ? a_hi : b_hi) - (a_lo > b_lo ? a_lo : b_lo);
    ExactSlab slab;
    slab.a_lo = rational_on(a_lo, lowest), slab.a_hi = rational_on(a_hi, lowest);
    slab.b_lo = rational_on(b_lo, lowest), slab.b_hi = rational_on(b_hi, lowest);
    slab.overlap = rational_on(overlap, lowest);
    slab.length = std::sqrt(static_cast<double>(std::abs(dir.x) + std::abs(dir.y) + std::abs(dir.z)));
    slabs.push_back(std::move(slab));
  }
  return slabs;
}

}  // namespace cc::exact
