// Whether a disagreement lies inside a party's band: conservative, two-sided and exact bands at
// and past their widths.
#include "harness/model/band.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cc::harness {
namespace {

TEST(WithinBand, ConservativeToleratesOnlyANearHit) {
  const Band b{0x1p-40, BandSides::conservative, 0, ""};
  EXPECT_TRUE(within_band(b, true, -0x1p-41));   // says hit, apart by less than the width
  EXPECT_TRUE(within_band(b, true, -0.0));
  EXPECT_FALSE(within_band(b, true, -0x1p-39));  // apart by more
  EXPECT_FALSE(within_band(b, false, 0x1p-50));  // a miss for touching shapes: never
  EXPECT_FALSE(within_band(b, false, 0));
}

TEST(WithinBand, TwoSidedAndExact) {
  const Band two{0x1p-20, BandSides::two_sided, 0, ""};
  EXPECT_TRUE(within_band(two, false, 0x1p-21));
  EXPECT_TRUE(within_band(two, true, -0x1p-21));
  EXPECT_FALSE(within_band(two, false, 0x1p-19));
  EXPECT_FALSE(within_band(two, true, NAN));
  EXPECT_FALSE(within_band({0, BandSides::exact, 0, ""}, true, -0.0));
}

}  // namespace
}  // namespace cc::harness
