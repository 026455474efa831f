// Both disc-against-wall methods against the exact reference (GMP rationals) on walls and discs
// placed to touch: on a side, at an end, a pillar, nearly parallel, tiny and huge, far from the
// origin; then nudged by a few ulps either way. A touch is never missed; a touch reported for a
// disc apart is within 2^-44 of the scale.
#include "collide/disc_walls.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "oracle/exact/exact_disc_walls.h"
#include "test_random.h"

namespace cc {
namespace {

using test::Random;

Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }

// A disc placed to touch the wall (up to the rounding of its construction), by one of several
// constructions, at a random scale and offset, then nudged by a few ulps.
Disc touching_disc(Random& random, Wall& wall) {
  const double scale = std::ldexp(1.0, random.below(200) - 100);
  const Vec2 offset = random.below(3) == 0 ? Vec2{} : std::ldexp(1.0, random.below(40)) * scale * Vec2{random.below(2) ? 1.0 : -1.0, random.below(2) ? 1.0 : -1.0};
  // Half of the cases on a grid of scale / 16, with radii 5 n scale / 64: their 3-4-5 offsets
  // and their pillars' offsets are exact, so they touch exactly.
  const bool grid = random.below(2) == 0;
  const auto coordinate = [&] { return grid ? (random.below(129) - 64) / 16.0 : random.between(-1, 1); };
  const Vec2 a = offset + scale * Vec2{coordinate(), coordinate()};
  Vec2 b = a + scale * Vec2{coordinate(), coordinate()};
  switch (random.below(4)) {
    case 0: b = a; break;                                                   // a pillar
    case 1: b = a + scale * 0x1p-30 * Vec2{random.between(-1, 1), 1}; break;  // a very short wall
    default: break;
  }
  wall = {a, b};
  const double r = random.below(5) == 0 ? 0.0 : (grid ? scale * 5 * (random.below(64) + 1) / 64 : scale * random.unit());
  const Vec2 w = b + (-1.0) * a;
  const double length = std::sqrt(w.x * w.x + w.y * w.y);
  Vec2 centre;
  switch (random.below(3)) {
    case 0: {  // beside the wall, projecting between its ends
      if (length == 0) return {a + Vec2{r, 0}, r};
      const Vec2 n{-w.y / length, w.x / length};
      centre = a + random.unit() * w + (random.below(2) ? r : -r) * n;
      break;
    }
    case 1: {  // beyond an end
      const double angle = random.between(0, 6.283185307179586);
      centre = (random.below(2) ? a : b) + r * Vec2{std::cos(angle), std::sin(angle)};
      break;
    }
    default:  // an exact 3-4-5 offset from an end
      centre = a + (r / 5) * Vec2{random.below(2) ? 3.0 : -3.0, random.below(2) ? 4.0 : -4.0};
  }
  const int nudges = random.below(9) - 4;
  for (int i = 0; i < std::abs(nudges); ++i) centre.y = std::nextafter(centre.y, nudges > 0 ? INFINITY : -INFINITY);
  return {centre, r};
}

TEST(DiscWallsExact, NeverMissesATouchAndStaysWithinTheBand) {
  Random random(20261124);
  int contacts = 0, exact_touches = 0, apart = 0, reported_apart_within_band = 0;
  for (int i = 0; i < 20000; ++i) {
    Wall wall;
    const Disc disc = touching_disc(random, wall);
    const exact::ExactDiscWall e = exact::exact_disc_wall(disc, wall);
    const bool one = test_disc_wall(disc, wall);
    const bool two = test_point_grown_wall(disc.center, disc.radius, wall);
    for (const bool says : {one, two}) {
      ASSERT_TRUE(exact::disc_wall_answer_right(e, disc, says, 0x1p-44))
          << (says ? "touch" : "miss") << " for disc (" << disc.center.x << ", " << disc.center.y << ") r " << disc.radius
          << ", wall (" << wall.a.x << ", " << wall.a.y << ")-(" << wall.b.x << ", " << wall.b.y << "), margin " << e.margin;
      reported_apart_within_band += says && !e.touches;
    }
    contacts += e.touches;
    apart += !e.touches;
    exact_touches += e.touches && e.distance2 == exact::rational(disc.radius) * exact::rational(disc.radius);
  }
  // The constructions must meet the boundary from both sides, and exactly.
  EXPECT_GT(contacts, 3000);
  EXPECT_GT(apart, 3000);
  EXPECT_GT(exact_touches, 500);
  std::printf("disc walls: %d contacts (%d exactly touching), %d apart, %d touches reported within the band\n", contacts,
              exact_touches, apart, reported_apart_within_band);
}

// A point or a small disc beside a long wall, apart from its line by 2^-26 to 2^-47 of the
// scale: the line test must measure the distance, not its square (as squares, the cross
// product's rounding let a point 2^-25 of the scale away count as touching).
TEST(DiscWallsExact, ASmallDiscBesideALongWallIsJudgedByItsDistance) {
  Random random(20261127);
  int apart_beyond_band = 0, touching = 0;
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::ldexp(1.0, random.below(200) - 100);
    const Vec2 a = scale * Vec2{random.between(-1, 1), random.between(-1, 1)};
    const Vec2 w = scale * Vec2{random.between(-1, 1), random.between(-1, 1)};
    const Wall wall{a, a + w};
    const double length = std::sqrt(w.x * w.x + w.y * w.y);
    if (length == 0) continue;
    const double gap = scale * std::ldexp(1 + random.unit(), -26 - random.below(22));
    const Vec2 n{-w.y / length, w.x / length};
    const Vec2 centre = a + random.between(0.1, 0.9) * w + (random.below(2) ? gap : -gap) * n;
    const double radius = std::array{0.0, gap * 0x1p-20, gap * (1 - 0x1p-10), gap * (1 + 0x1p-10)}[random.below(4)];
    const Disc disc{centre, radius};
    const exact::ExactDiscWall e = exact::exact_disc_wall(disc, wall);
    for (const bool says : {test_disc_wall(disc, wall), test_point_grown_wall(centre, radius, wall)}) {
      ASSERT_TRUE(exact::disc_wall_answer_right(e, disc, says, 0x1p-44))
          << (says ? "touch" : "miss") << " for disc (" << centre.x << ", " << centre.y << ") r " << radius << ", wall ("
          << wall.a.x << ", " << wall.a.y << ")-(" << wall.b.x << ", " << wall.b.y << "), margin " << e.margin;
    }
    apart_beyond_band += !e.touches && e.margin < -0x1p-43;
    touching += e.touches;
  }
  EXPECT_GT(apart_beyond_band, 5000);  // the cases the squared test got wrong
  EXPECT_GT(touching, 2000);
}

}  // namespace
}  // namespace cc
