// The values every generator builds on reach all they declare: each part of coordinate() and
// length() that the range allows is drawn, and each part's parameter reaches both ends of its
// declared range (values.h, kDeclaredRanges). A branch never taken, or a range shifted by one,
// fails here while every statistical property may stay green.
#include "harness/generation/values.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

namespace cc::harness {
namespace {

const char* const kPartNames[] = {"zero",     "small_integer",      "quarter",           "repeat",    "nudge",
                                  "power_of_two", "generic",        "minus_zero",        "smallest_subnormal",
                                  "largest_subnormal", "subnormal", "tiny",              "huge",      "nan",
                                  "infinity", "minus_infinity",     "zero_length",       "moderate_length"};
static_assert(std::size(kPartNames) == static_cast<std::size_t>(Part::count));

TEST(ValueSource, ZeroChoicesGiveTheSimplestValue) {
  ReplayChoices zeros({});
  ValueSource v(zeros, {});
  EXPECT_EQ(v.coordinate(), 0.0);
  EXPECT_EQ(v.length(), 0.0);
}

TEST(ValueSource, MeetsTheBoundaryValues) {
  RandomChoices c(1);
  ValueSource v(c, {8, true, true, true});
  bool zero = false, neg_zero = false, subnormal = false, nan = false, inf = false, huge = false, repeated = false;
  std::set<double> seen;
  for (int i = 0; i < 20000; ++i) {
    const double x = v.coordinate();
    zero |= x == 0 && !std::signbit(x);
    neg_zero |= x == 0 && std::signbit(x);
    subnormal |= std::fpclassify(x) == FP_SUBNORMAL;
    nan |= std::isnan(x);
    inf |= std::isinf(x);
    huge |= std::isfinite(x) && std::fabs(x) > 0x1p100;
    if (std::isfinite(x) && x != 0 && !seen.insert(x).second) repeated = true;
  }
  EXPECT_TRUE(zero && neg_zero && subnormal && nan && inf && huge && repeated);
}

// 400,000 coordinates and lengths, in cases of 12 values each (a source per case, as the
// generators use them), their parts summed.
PartsDrawn draw_many(const ValueRange& range) {
  PartsDrawn all;
  RandomChoices choices(2026);
  for (int n = 0; n < 400000 / 12; ++n) {
    ValueSource v(choices, range);
    for (int i = 0; i < 6; ++i) (void)v.coordinate(), (void)v.length();
    const PartsDrawn& drawn = v.parts();
    for (std::size_t p = 0; p < all.times.size(); ++p) {
      if (drawn.times[p] == 0) continue;
      all.times[p] += drawn.times[p];
      all.least[p] = std::min(all.least[p], drawn.least[p]);
      all.greatest[p] = std::max(all.greatest[p], drawn.greatest[p]);
    }
  }
  return all;
}

TEST(ValueSource, DrawsEveryPartAndReachesBothEndsOfEveryRange) {
  const ValueRange everything{8, true, true, true};
  const PartsDrawn drawn = draw_many(everything);
  for (std::size_t p = 0; p < drawn.times.size(); ++p) {
    EXPECT_GT(drawn.times[p], 0u) << kPartNames[p] << " is never drawn";
  }
  for (const DeclaredRange& r : kDeclaredRanges) {
    const auto p = static_cast<std::size_t>(r.part);
    EXPECT_EQ(drawn.least[p], r.lo) << kPartNames[p];
    EXPECT_EQ(drawn.greatest[p], r.hi) << kPartNames[p];
  }
  const auto generic = static_cast<std::size_t>(Part::generic);
  EXPECT_EQ(drawn.least[generic], -everything.max_exponent);
  EXPECT_EQ(drawn.greatest[generic], everything.max_exponent);
}

// A range that leaves out the extremes draws none of them, and the generic exponent follows it.
TEST(ValueSource, DrawsOnlyWhatItsRangeAllows) {
  const ValueRange plain{30, false, false, false};
  const PartsDrawn drawn = draw_many(plain);
  for (const Part p : {Part::minus_zero, Part::smallest_subnormal, Part::largest_subnormal, Part::subnormal, Part::tiny,
                       Part::huge, Part::nan, Part::infinity, Part::minus_infinity}) {
    EXPECT_EQ(drawn.times[static_cast<std::size_t>(p)], 0u) << kPartNames[static_cast<std::size_t>(p)];
  }
  const auto generic = static_cast<std::size_t>(Part::generic);
  EXPECT_EQ(drawn.least[generic], -30);
  EXPECT_EQ(drawn.greatest[generic], 30);
}

TEST(WithOneComponent, ReplacesEachComponentInTurnAndNoOther) {
  RandomChoices c(7);
  std::set<int> replaced;
  for (int i = 0; i < 100; ++i) {
    const Vec3 p = with_one_component({1, 2, 3}, NAN, c);
    int nans = 0;
    for (int k = 0; k < 3; ++k) {
      if (std::isnan(p[k])) ++nans, replaced.insert(k);
      else EXPECT_EQ(p[k], k + 1);
    }
    EXPECT_EQ(nans, 1);
  }
  EXPECT_EQ(replaced.size(), 3u);
}

}  // namespace
}  // namespace cc::harness
