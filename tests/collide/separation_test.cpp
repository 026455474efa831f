// Separation::certified_lazily against Separation::certified: the same bits for any lower bound,
// the bound asked for only where the answer depends on it, and an early stop at a bound that is
// enough giving the answer of the whole one.
#include "collide/separation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

namespace cc {
namespace {

bool same_bits(const Separation& x, const Separation& y) {
  const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  return bits(x.distance) == bits(y.distance) && x.on_a == y.on_a && x.on_b == y.on_b &&
         bits(x.distance_error) == bits(y.distance_error) && bits(x.point_error) == bits(y.point_error);
}

TEST(CertifiedLazily, GivesTheBitsOfCertifiedAndAsksForTheBoundOnlyWhereItCounts) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1), share(0, 1);
  int asked = 0, not_asked = 0, stopped = 0;
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::ldexp(1.0, static_cast<int>(unit(rng) * 40));
    const Vec3 on_a{scale * unit(rng), scale * unit(rng), scale * unit(rng)};
    // Witnesses from far apart down to a few ULPs apart, where the distance is within their bound.
    const double apart = std::ldexp(scale, -static_cast<int>(share(rng) * 60));
    const Vec3 on_b = on_a + apart * Vec3{unit(rng), unit(rng), unit(rng)};
    const double point_error = 32 * fp::u * scale;
    const double d = length(on_b - on_a);
    // Two lower bounds: below the distance by up to its whole, or by a few of its rounding.
    const double g1 = std::max(0.0, d * (1 - share(rng))), g2 = std::max(0.0, d - 100 * fp::u * scale * share(rng));
    const Separation whole = Separation::certified(on_a, on_b, point_error, std::max(g1, g2));
    bool called = false;
    const Separation lazy = Separation::certified_lazily(on_a, on_b, point_error, [&](const auto& enough) {
      called = true;
      if (enough(g1)) {
        ++stopped;
        return g1;
      }
      return std::max(g1, g2);
    });
    ASSERT_TRUE(same_bits(whole, lazy)) << i;
    // Not asked for: every lower bound gives the same answer, 0 among them.
    if (!called) {
      ASSERT_TRUE(same_bits(Separation::certified(on_a, on_b, point_error, 0), lazy)) << i;
    }
    ++(called ? asked : not_asked);
  }
  EXPECT_GT(asked, 1000);
  EXPECT_GT(not_asked, 1000);
  EXPECT_GT(stopped, 100);
}

}  // namespace
}  // namespace cc
