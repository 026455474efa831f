// test_disc_wall and test_point_grown_wall: touching a wall's side, its end, a pillar; apart by
// an ulp; degenerate discs; scaled and far from the origin; out of contract; the ends' order.
#include "collide/disc_walls.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace cc {
namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();

// Both methods' answer, required to agree, for both orders of the wall's ends (bit for bit).
bool touches(const Disc& disc, const Wall& wall) {
  const Wall reversed{wall.b, wall.a};
  const bool one = test_disc_wall(disc, wall);
  const bool two = test_point_grown_wall(disc.center, disc.radius, wall);
  EXPECT_EQ(one, test_disc_wall(disc, reversed));
  EXPECT_EQ(two, test_point_grown_wall(disc.center, disc.radius, reversed));
  EXPECT_EQ(one, two) << "the methods differ";
  return one;
}

const Wall kWall{{0, 0}, {4, 0}};

TEST(DiscWalls, TouchingTheSideIsAContact) {
  EXPECT_TRUE(touches({{2, 0.5}, 0.5}, kWall));
  EXPECT_TRUE(touches({{2, -0.5}, 0.5}, kWall));
  EXPECT_TRUE(touches({{2, 0.25}, 0.5}, kWall));  // crossing it
  EXPECT_TRUE(touches({{2, 0}, 0}, kWall));       // a point on it
}

TEST(DiscWalls, AnUlpApartFromTheSideIsNotAContactAtUnitScale) {
  // Apart by 2^-40 of the scale, beyond the band of 2^-44: a miss.
  EXPECT_FALSE(touches({{2, 0.5 + 0x1p-40}, 0.5}, kWall));
  EXPECT_FALSE(touches({{2, 0.75}, 0.5}, kWall));
}

TEST(DiscWalls, APointBesideADiagonalWallIsApartByItsDistance) {
  // A point near (2^-16, 2^-16), 9.1e-13 (2^-40) from the line y = x, the scale being 1 (the
  // wall's end): apart beyond the band (the line test once compared squares and let it touch).
  const Disc point{{1.525877385519498e-05, 1.5258775141413494e-05}, 0};
  EXPECT_FALSE(test_disc_wall(point, {{0, 0}, {1, 1}}));
  EXPECT_FALSE(test_point_grown_wall(point.center, 0, {{0, 0}, {1, 1}}));
  EXPECT_TRUE(test_disc_wall({point.center, 1e-12}, {{0, 0}, {1, 1}}));  // a disc reaching it
}

TEST(DiscWalls, TouchingAnEndAlongA345DirectionIsAContact) {
  // (4 + 3/16, 4/16) is 5/16 from the end (4, 0).
  EXPECT_TRUE(touches({{4 + 0.1875, 0.25}, 0.3125}, kWall));
  EXPECT_TRUE(touches({{-0.1875, -0.25}, 0.3125}, kWall));
  EXPECT_FALSE(touches({{4 + 0.1875 + 0x1p-40, 0.25}, 0.3125}, kWall));
  // Beyond the end, level with the wall: the line is within r, the segment is not.
  EXPECT_FALSE(touches({{4.5, 0}, 0.25}, kWall));
  EXPECT_TRUE(touches({{4.25, 0}, 0.25}, kWall));
}

TEST(DiscWalls, APillarIsAPoint) {
  const Wall pillar{{1, 1}, {1, 1}};
  EXPECT_TRUE(touches({{1.1875, 1.25}, 0.3125}, pillar));
  EXPECT_TRUE(touches({{1, 1}, 0}, pillar));
  EXPECT_FALSE(touches({{1.25, 1.25}, 0.3125}, pillar));
  EXPECT_FALSE(touches({{1, 1 + 0x1p-40}, 0}, pillar));
}

TEST(DiscWalls, DiagonalWallsAndWallsThroughTheCentre) {
  const Wall diagonal{{0, 0}, {3, 4}};  // unit normal (-4, 3) / 5
  // (1.5, 2) on the wall, moved by 5/8 along the normal: exactly 5/8 from it, between the ends.
  EXPECT_TRUE(touches({{1.5 - 0.5, 2 + 0.375}, 0.625}, diagonal));
  EXPECT_FALSE(touches({{1.5 - 0.5 * (1 + 0x1p-30), 2 + 0.375 * (1 + 0x1p-30)}, 0.625}, diagonal));
  EXPECT_TRUE(touches({{1.5, 2}, 0.125}, diagonal));  // the centre on the wall
}

TEST(DiscWalls, ScaledByPowersOfTwoTheAnswersStay) {
  for (const int e : {-1000, -500, -60, 0, 60, 480}) {
    const double s = std::ldexp(1.0, e);
    const Wall w{{0, 0}, {4 * s, 0}};
    EXPECT_TRUE(touches({{2 * s, 0.5 * s}, 0.5 * s}, w)) << e;
    EXPECT_TRUE(touches({{(4 + 0.1875) * s, 0.25 * s}, 0.3125 * s}, w)) << e;
    EXPECT_FALSE(touches({{2 * s, 0.75 * s}, 0.5 * s}, w)) << e;
  }
}

TEST(DiscWalls, FarFromTheOriginTouchingStaysExact) {
  const double far = 0x1p30;
  const Wall w{{far, far}, {far + 1, far}};
  EXPECT_TRUE(touches({{far + 0.5, far + 0.3125}, 0.3125}, w));
  EXPECT_TRUE(touches({{far + 1.1875, far + 0.25}, 0.3125}, w));
  // Apart by 2^-20 at magnitude 2^30 (2^-50 of the scale): either answer; by 2^-10, a miss.
  EXPECT_FALSE(touches({{far + 0.5, far + 0.3125 + 0x1p-10}, 0.3125}, w));
}

TEST(DiscWalls, OutOfContractInputsGiveNoContact) {
  for (const Disc& d : {Disc{{kNan, 0}, 1}, Disc{{0, INFINITY}, 1}, Disc{{2, 0}, -1}, Disc{{2, 0}, kNan}, Disc{{2, 0}, INFINITY}}) {
    EXPECT_FALSE(test_disc_wall(d, kWall));
    EXPECT_FALSE(test_point_grown_wall(d.center, d.radius, kWall));
  }
  const Wall bad{{0, 0}, {kNan, 0}};
  EXPECT_FALSE(test_disc_wall({{0, 0}, 1}, bad));
  EXPECT_FALSE(test_point_grown_wall({0, 0}, 1, bad));
}

TEST(DiscWalls, DiscWallsListsTheTouchedWallsByEitherMethod) {
  const std::vector<Wall> walls{{{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{0, 1}, {1, 1}}, {{5, 5}, {6, 5}}};
  const Disc disc{{0.6875, 0.3125}, 0.3125};  // touches the bottom and the right wall exactly
  for (const DiscWallsMethod m : {DiscWallsMethod::disc_against_walls, DiscWallsMethod::point_against_grown_walls}) {
    EXPECT_EQ(disc_walls(disc, walls, m), (std::vector<std::uint32_t>{0, 1}));
  }
}

}  // namespace
}  // namespace cc
