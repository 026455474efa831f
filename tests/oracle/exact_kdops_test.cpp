// The exact k-DOP slabs: for every direction set, each set's least and greatest projection and
// the overlap, checked against their definition in rationals, on point sets at scales from the
// subnormals to 2^1000, with shared points (touching slabs) and single points.
#include "oracle/exact/exact_kdops.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "collide/kdop.h"

namespace cc::exact {
namespace {

TEST(ExactKdopSlabs, AreTheExtremeProjectionsOfEachSet) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(-1, 1);
  int touching = 0, apart = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const int k = std::array{6, 14, 16, 18, 24, 26}[trial % 6];
    const int scale = static_cast<int>(trial % 2100) - 1074;
    const auto point = [&] {
      // Each coordinate at its own exponent near the scale, some of them 0.
      Vec3 p;
      for (int i = 0; i < 3; ++i) p[i] = random() % 7 == 0 ? 0.0 : std::ldexp(uniform(random), std::min(scale + static_cast<int>(random() % 40), 1000));
      return p;
    };
    std::vector<Vec3> a(1 + trial % 5), b(1 + trial % 3);
    for (Vec3& p : a) p = point();
    for (Vec3& p : b) p = point();
    if (trial % 4 == 0) b[0] = a[0];  // a shared point: every slab overlaps, some by 0
    const std::vector<ExactSlab> slabs = exact_kdop_slabs(k, a, b);
    const auto dirs = kdop_directions(k);
    ASSERT_EQ(slabs.size(), dirs.size());
    for (std::size_t i = 0; i < dirs.size(); ++i) {
      const QVec3 d{dirs[i].x, dirs[i].y, dirs[i].z};
      const auto extent = [&d](const std::vector<Vec3>& points) {
        Rational lo = dot(d, rational(points[0])), hi = lo;
        for (const Vec3& p : points) lo = std::min(lo, dot(d, rational(p))), hi = std::max(hi, dot(d, rational(p)));
        return std::pair{lo, hi};
      };
      const auto [a_lo, a_hi] = extent(a);
      const auto [b_lo, b_hi] = extent(b);
      ASSERT_EQ(slabs[i].a_lo, a_lo) << "trial " << trial << " direction " << i;
      ASSERT_EQ(slabs[i].a_hi, a_hi) << "trial " << trial << " direction " << i;
      ASSERT_EQ(slabs[i].b_lo, b_lo) << "trial " << trial << " direction " << i;
      ASSERT_EQ(slabs[i].b_hi, b_hi) << "trial " << trial << " direction " << i;
      ASSERT_EQ(slabs[i].overlap, std::min(a_hi, b_hi) - std::max(a_lo, b_lo)) << "trial " << trial << " direction " << i;
      ASSERT_EQ(slabs[i].length, std::sqrt(static_cast<double>(std::abs(dirs[i].x) + std::abs(dirs[i].y) + std::abs(dirs[i].z))));
      touching += sgn(slabs[i].overlap) == 0;
      apart += sgn(slabs[i].overlap) < 0;
    }
  }
  EXPECT_GT(touching, 100);
  EXPECT_GT(apart, 100);
}

}  // namespace
}  // namespace cc::exact
