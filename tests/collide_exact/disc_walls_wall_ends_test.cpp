// Rare configurations reached on purpose: a disc beyond a wall's end, at exactly its radius from
// the end, then moved by up to 4 ulps in each coordinate either way, at every scale from the
// subnormal range (coordinates small multiples of 2^-1074) up to the domain's 2^500. Both methods
// against the exact reference (GMP rationals): a touch is never missed; a touch reported for a
// disc apart is within 2^-44 of the scale (disc_walls.h). The generator must reach subnormal
// coordinates, discs exactly touching, discs nearest to the end (beyond it), and both answers.
#include "collide/disc_walls.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "oracle/exact/exact_disc_walls.h"
#include "test_random.h"

namespace cc {
namespace {

using test::Random;

double nudged(double x, int ulps) {
  for (int i = 0; i < std::abs(ulps); ++i)
    x = std::nextafter(x, ulps > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity());
  return x;
}

bool subnormal(double x) { return x != 0 && std::fabs(x) < std::numeric_limits<double>::min(); }

struct Case {
  Disc disc;
  Wall wall;
};

// A wall on a grid of spacing 2^k (k from -1074 to 492, a third of the cases within 60 binades
// of the subnormal range), a disc centred at an exact Pythagorean offset of length r from the
// end a, pointing away from the wall (beyond the end: (c - a) . (b - a) < 0), then nudged.
Case wall_end_case(Random& random) {
  const int k = random.below(3) == 0 ? random.in(-1074, -1014) : random.in(-1074, 492);
  const double s = std::ldexp(1.0, k);
  // Small integers so that at k = -1074 every coordinate is a small multiple of 2^-1074; a
  // translation of up to 2^6 grid steps sometimes (coordinates stay below 2^8 steps, exact).
  const auto step = [&](int h) { return random.in(-h, h); };
  const int tx = random.below(2) ? step(64) : 0, ty = random.below(2) ? step(64) : 0;
  const int ax = tx + step(16), ay = ty + step(16);
  int wx = 0, wy = 0;
  while (wx == 0 && wy == 0) wx = step(16), wy = step(16);
  const Vec2 a{s * ax, s * ay}, b{s * (ax + wx), s * (ay + wy)};
  static constexpr std::array<std::array<int, 3>, 6> triples{{{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29}, {1, 0, 1}}};
  const auto& [p, q, h] = triples[random.below(6)];
  const int m = random.in(1, 2);
  // One of the eight signed, swapped offsets that points away from b - a (in grid units, exactly).
  int ox = 0, oy = 0;
  do {
    const bool swap = random.below(2);
    ox = m * (swap ? q : p) * (random.below(2) ? 1 : -1);
    oy = m * (swap ? p : q) * (random.below(2) ? 1 : -1);
  } while (ox * wx + oy * wy >= 0);
  Vec2 c{s * (ax + ox), s * (ay + oy)};
  const double r = s * m * h;
  // A quarter of the discs left exactly touching; the others nudged by up to 4 ulps each way.
  if (random.below(4) != 0) c = {nudged(c.x, random.in(-4, 4)), nudged(c.y, random.in(-4, 4))};
  // Half of the cases with the ends swapped: the end the disc is beyond is then b.
  return random.below(2) ? Case{{c, r}, {a, b}} : Case{{c, r}, {b, a}};
}

TEST(DiscWallsWallEnds, DiscsWithinUlpsOfAWallsEndAtEveryScaleAreJudgedWithinTheContract) {
  Random random(20261128);
  int subnormal_cases = 0, deep_subnormal = 0, exact_touches = 0, overlapping = 0, apart = 0, beyond_end = 0;
  std::array<std::array<int, 2>, 2> answers{};  // [method][says touch]
  int reported_apart_within_band = 0, huge = 0, apart_beyond_band = 0;
  for (int i = 0; i < 100000; ++i) {
    const Case t = wall_end_case(random);
    const Disc& disc = t.disc;
    const Wall& wall = t.wall;
    const exact::ExactDiscWall e = exact::exact_disc_wall(disc, wall);
    const std::array<bool, 2> says{test_disc_wall(disc, wall), test_point_grown_wall(disc.center, disc.radius, wall)};
    for (int method = 0; method < 2; ++method) {
      ASSERT_TRUE(exact::disc_wall_answer_right(e, disc, says[method], 0x1p-44))
          << (method == 0 ? "test_disc_wall" : "test_point_grown_wall") << " says " << (says[method] ? "touch" : "miss")
          << std::hexfloat << " for disc (" << disc.center.x << ", " << disc.center.y << ") r " << disc.radius << ", wall ("
          << wall.a.x << ", " << wall.a.y << ")-(" << wall.b.x << ", " << wall.b.y << "), margin " << e.margin;
      ++answers[method][says[method]];
      reported_apart_within_band += says[method] && !e.touches;
    }
    const std::array<double, 7> values{disc.center.x, disc.center.y, wall.a.x, wall.a.y, wall.b.x, wall.b.y, disc.radius};
    bool any_subnormal = false, all_tiny = true;
    for (double v : values) {
      any_subnormal |= subnormal(v);
      all_tiny &= std::fabs(v) < std::numeric_limits<double>::min();
    }
    subnormal_cases += any_subnormal;
    deep_subnormal += all_tiny && disc.radius != 0;
    huge += e.scale > 0x1p400;
    exact_touches += e.touches && sgn(e.slack) == 0;
    overlapping += sgn(e.slack) > 0;
    apart += !e.touches;
    apart_beyond_band += !e.touches && e.margin < -0x1p-44;
    beyond_end += !e.pillar && (e.t == 0 || e.t == 1);
  }
  std::printf("disc at a wall's end: %d with subnormal coordinates (%d wholly below 2^-1022), %d at scales above 2^400, "
              "%d exactly touching, %d overlapping, %d apart (%d beyond the band), %d nearest to an end; test_disc_wall %d touch / %d miss, "
              "test_point_grown_wall %d touch / %d miss, %d touches reported within the band\n",
              subnormal_cases, deep_subnormal, huge, exact_touches, overlapping, apart, apart_beyond_band, beyond_end, answers[0][1], answers[0][0],
              answers[1][1], answers[1][0], reported_apart_within_band);
  EXPECT_GT(subnormal_cases, 10000);
  EXPECT_GT(deep_subnormal, 8000);
  EXPECT_GT(huge, 3000);
  EXPECT_GT(exact_touches, 10000);
  EXPECT_GT(overlapping, 10000);
  EXPECT_GT(apart, 10000);
  EXPECT_GT(apart_beyond_band, 5000);  // where a touch is wrong
  EXPECT_GT(beyond_end, 90000);
  for (const auto& method : answers) {
    EXPECT_GT(method[0], 8000);
    EXPECT_GT(method[1], 8000);
  }
}

}  // namespace
}  // namespace cc
