// k-DOP fitting is conservative under rounding: every input point lies inside the fitted k-DOP
// in exact arithmetic, for every direction set.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "collide/kdop.h"
#include "harness/input_json.h"
#include "harness/values.h"
#include "oracle/exact/rational.h"
#include "properties/property.h"

namespace cc::test {
namespace {

template <int K>
void check_fit(const std::vector<Vec3>& points, Met& met) {
  const Kdop<K> dop = fit_kdop<K>(points);
  const auto dirs = kdop_directions<K>();
  harness::Features f;
  f.degenerate = points.size() == 1;
  for (int i = 0; i < K / 2; ++i) {
    const exact::QVec3 d{dirs[i].x, dirs[i].y, dirs[i].z};
    const bool diagonal = (dirs[i].x != 0) + (dirs[i].y != 0) + (dirs[i].z != 0) > 1;
    std::vector<exact::Rational> seen;
    for (const Vec3& p : points) {
      const exact::Rational s = dot(d, exact::rational(p));
      if (s < exact::rational(dop.lo[i]) || s > exact::rational(dop.hi[i])) {
        RC_FAIL("k = " + std::to_string(K) + ", slab " + std::to_string(i) + ": a point lies outside the fitted k-DOP");
      }
      if (diagonal && (s == exact::rational(dop.lo[i]) || s == exact::rational(dop.hi[i]))) f.touching = true;
      for (const exact::Rational& t : seen) f.parallel |= diagonal && t == s;
      seen.push_back(s);
    }
  }
  met.count(f);
}

TEST(FitKdop, EveryPointLiesInsideTheFittedKdopExactly) {
  Met met;
  const bool passed = check_property_with_choices("fit_kdop is conservative", 3000, [&](harness::Choices& c) {
    harness::ValueSource values(c, {});
    std::vector<Vec3> points;
    const auto n = 1 + c.draw(6);
    for (std::uint64_t i = 0; i < n; ++i) points.push_back(c.chance(30) && !points.empty() ? points.back() : values.point());
    switch (c.draw(6)) {
      case 0: check_fit<6>(points, met); break;
      case 1: check_fit<14>(points, met); break;
      case 2: check_fit<16>(points, met); break;
      case 3: check_fit<18>(points, met); break;
      case 4: check_fit<24>(points, met); break;
      default: check_fit<26>(points, met);
    }
  });
  EXPECT_TRUE(passed);
  expect_met_the_boundary("fit_kdop is conservative", harness::QueryKind::kdop_kdop, met);
}

}  // namespace
}  // namespace cc::test
