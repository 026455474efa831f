#include "harness/formats/number_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace cc::harness {
namespace {

TEST(FormatDouble, IsTheShortestRoundTripDecimal) {
  EXPECT_EQ(format_double(0.1), "0.1");
  EXPECT_EQ(format_double(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(format_double(1), "1");
  EXPECT_EQ(format_double(-0.0), "-0");
  EXPECT_EQ(format_double(std::numeric_limits<double>::denorm_min()), "5e-324");
  EXPECT_EQ(format_double(NAN), "nan");
  EXPECT_EQ(format_double(INFINITY), "inf");
  EXPECT_EQ(format_double(-INFINITY), "-inf");
}

TEST(ParseDouble, ReadsBackEveryDoubleExactly) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 20000; ++i) {
    std::uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (std::isnan(x)) continue;
    const auto back = parse_double(format_double(x));
    ASSERT_TRUE(back.has_value()) << format_double(x);
    ASSERT_EQ(std::memcmp(&*back, &x, sizeof x), 0) << format_double(x);  // -0 stays -0
  }
  EXPECT_TRUE(std::isnan(*parse_double("nan")));
  EXPECT_EQ(*parse_double("-inf"), -INFINITY);
  // A NaN keeps its sign (x86's inf - inf is -nan): a peer may answer the two differently.
  volatile double inf = INFINITY;
  const double made = inf - inf;
  ASSERT_TRUE(std::isnan(made));
  EXPECT_EQ(format_double(made), std::signbit(made) ? "-nan" : "nan");
  EXPECT_EQ(format_double(-made), std::signbit(made) ? "nan" : "-nan");
  EXPECT_FALSE(std::signbit(*parse_double("nan")));
  EXPECT_TRUE(std::signbit(*parse_double("-nan")));
  EXPECT_TRUE(std::isnan(*parse_double("-nan")));
  EXPECT_EQ(*parse_double("+2.5"), 2.5);
}

TEST(ParseDouble, RefusesAnythingElse) {
  for (const char* bad : {"", "0.1x", "x", "1e", "--1", "infinity", "NaN", "nan(1)", " 1", "1 ", "0x10", "++1"}) {
    EXPECT_FALSE(parse_double(bad).has_value()) << bad;
  }
}

}  // namespace
}  // namespace cc::harness
