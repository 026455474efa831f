// Bounded: the exact value of every computation lies within its bound, at every scale down to
// the subnormals; exact operations on exact values keep a bound of 0; overflow shows.
#include "oracle/exact/bounded.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "oracle/exact/rational.h"

namespace cc::exact {
namespace {

struct Tracked {
  Bounded b;
  Rational q;  // the exact value b stands for
};

Tracked input(double x) { return {{x, 0}, rational(x)}; }

// |q - v| <= e, in rationals.
bool holds(const Tracked& t) { return abs(t.q - rational(t.b.v)) <= rational(t.b.e); }

TEST(Bounded, TheExactValueIsWithinTheBoundAtEveryScale) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> uniform(-1, 1);
  int tight = 0, checked = 0, first_steps = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    // Exponents from deep in the subnormals to 2^300; some values share a scale (cancellation).
    const int scale = static_cast<int>(trial % 1400) - 1100;
    const auto draw = [&] {
      const int spread = static_cast<int>(random() % 8);
      return std::ldexp(uniform(random), scale + (trial % 3 == 0 ? 0 : spread));
    };
    std::vector<Tracked> values;
    for (int i = 0; i < 4; ++i) values.push_back(input(draw()));
    // A chain of the filter's operations: differences, products, sums of products, min, max, abs.
    for (int step = 0; step < 12; ++step) {
      const Tracked& x = values[random() % values.size()];
      const Tracked& y = values[random() % values.size()];
      Tracked r;
      switch (random() % 6) {
        case 0: r = {x.b + y.b, x.q + y.q}; break;
        case 1: r = {x.b - y.b, x.q - y.q}; break;
        case 2: r = {x.b * y.b, x.q * y.q}; break;
        case 3: r = {min(x.b, y.b), x.q < y.q ? x.q : y.q}; break;
        case 4: r = {max(x.b, y.b), x.q > y.q ? x.q : y.q}; break;
        default: r = {abs(x.b), abs(x.q)}; break;
      }
      if (!r.b.finite()) continue;
      ++checked;
      ASSERT_TRUE(holds(r)) << "trial " << trial << " step " << step << ": " << r.b.v << " +- " << r.b.e;
      // Not loose: one operation on exact values is bounded by about its own rounding error.
      if (x.b.e == 0 && y.b.e == 0) {
        ++first_steps;
        tight += r.b.e <= 0x1p-52 * std::fabs(r.b.v) + 0x1p-1071;
      }
      values.push_back(r);
    }
  }
  EXPECT_GT(checked, 150000);
  EXPECT_GT(first_steps, 10000);
  EXPECT_EQ(tight, first_steps);
}

TEST(Bounded, ExactOperationsOnExactValuesStayExact) {
  const Bounded one{1, 0}, two{2, 0}, third{1.0 / 3, 0}, zero{0, 0};
  EXPECT_FALSE((one + two).zero());
  EXPECT_EQ((one + two).e, 0);
  EXPECT_EQ((one - one).v, 0);
  EXPECT_TRUE((one - one).zero());
  EXPECT_TRUE((zero * Bounded{0x1p-1074, 0}).zero());     // a zero factor: exact at any scale
  EXPECT_EQ((third * two).e, 0);                          // a power of two
  EXPECT_EQ((Bounded{1.5, 0} - Bounded{1.25, 0}).e, 0);   // Sterbenz
  EXPECT_GT((third * third).e, 0);                        // rounded
  EXPECT_TRUE((third * third).certain());
  // A product whose error may round in the subnormals is never called exact.
  const Bounded tiny = Bounded{0x1.8p-600, 0} * Bounded{0x1.8p-480, 0};
  EXPECT_GT(tiny.e, 0);
  EXPECT_TRUE(abs(rational(0x1.8p-600) * rational(0x1.8p-480) - rational(tiny.v)) <= rational(tiny.e));
  // An error in an operand never disappears, even when the product underflows to 0.
  EXPECT_GT((Bounded{0x1p-600, 0x1p-700} * Bounded{0x1p-600, 0}).e, 0);
  EXPECT_FALSE((Bounded{0, 0x1p-1074}).certain());
}

TEST(Bounded, OverflowIsNeverFinite) {
  const Bounded huge{0x1p1000, 0};
  EXPECT_FALSE((huge * huge).finite());
  EXPECT_FALSE((huge * huge - huge * huge).finite());
  EXPECT_FALSE((Bounded{0x1.fffffffffffffp1023, 0} + Bounded{0x1p1000, 0}).finite());
}

TEST(LengthBounds, HoldTheExactLengthOrGiveUp) {
  const BoundedVec3 v{{3, 0}, {4, 0}, {0, 0}};
  const LengthBounds n = length_bounds(v);
  EXPECT_LE(n.lo, 5);
  EXPECT_GE(n.hi, 5);
  EXPECT_GT(n.lo, 5 - 1e-9);
  // An error as large as the vector: the lower end cannot tell it from 0.
  EXPECT_LE(length_bounds({{1, 2}, {0, 0}, {0, 0}}).lo, 0);
  // Squares that underflow, and squares that overflow: no bounds.
  EXPECT_LE(length_bounds({{0x1p-460, 0}, {0, 0}, {0, 0}}).lo, 0);
  EXPECT_FALSE(std::isfinite(length_bounds({{0x1p600, 0}, {0, 0}, {0, 0}}).hi));
}

}  // namespace
}  // namespace cc::exact
