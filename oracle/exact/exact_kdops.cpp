#include "oracle/exact/exact_kdops.h"

#include <cmath>
#include <cstdlib>
#include <tuple>

#include "collide/kdop.h"

namespace cc::exact {

std::vector<ExactSlab> exact_kdop_slabs(int k, const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  std::vector<ExactSlab> slabs;
  for (const KdopDirection& dir : kdop_directions(k)) {
    const QVec3 d{dir.x, dir.y, dir.z};
    const auto extent = [&d](const std::vector<Vec3>& points) {
      Rational lo = dot(d, rational(points[0])), hi = lo;
      for (const Vec3& p : points) {
        const Rational s = dot(d, rational(p));
        if (s < lo) lo = s;
        if (s > hi) hi = s;
      }
      return std::pair{lo, hi};
    };
    ExactSlab s;
    std::tie(s.a_lo, s.a_hi) = extent(a);
    std::tie(s.b_lo, s.b_hi) = extent(b);
    s.overlap = (s.a_hi < s.b_hi ? s.a_hi : s.b_hi) - (s.a_lo > s.b_lo ? s.a_lo : s.b_lo);
    s.length = std::sqrt(static_cast<double>(std::abs(dir.x) + std::abs(dir.y) + std::abs(dir.z)));
    slabs.push_back(s);
  }
  return slabs;
}

}  // namespace cc::exact
