// distance_obb_obb on configurations whose answers are known exactly: apart face to face, edge to
// edge and corner to face, touching, overlapping through a face and through crossing edges, boxes
// with parallel edges (the same rotation), flat boxes, swapped arguments, scales, and outside the
// domain. tests/collide_exact/obb_distance_test.cpp checks the bounds in rationals.
#include "collide/obb_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "rotations.h"
#include "test_random.h"

namespace cc {
namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kRoot2 = std::numbers::sqrt2;

void expect_vec(const Vec3& got, const Vec3& want, double within) {
  EXPECT_NEAR(got.x, want.x, within);
  EXPECT_NEAR(got.y, want.y, within);
  EXPECT_NEAR(got.z, want.z, within);
}

Obb cube(const Vec3& center, double half = 1, const Mat3& axes = Mat3::identity()) {
  return {center, {half, half, half}, axes};
}

// A cube turned 45 degrees about y: its top is an edge along y at height sqrt 2 above its centre.
Mat3 edge_up_along_y() { return test::rotation(0, 0, std::numbers::pi / 4); }
// A cube turned 45 degrees about x: its bottom is an edge along x at sqrt 2 below its centre.
Mat3 edge_down_along_x() { return test::rotation(std::numbers::pi / 4, 0, 0); }

TEST(DistanceObbObb, ApartFaceToFace) {
  const Separation s = distance_obb_obb(cube({0, 0, 0}), cube({3.5, 0.25, -0.5}));
  EXPECT_NEAR(s.distance, 1.5, s.distance_error);
  EXPECT_LE(s.distance_error, 1e-12);
  EXPECT_NEAR(s.on_a.x, 1, 1e-15);
  EXPECT_NEAR(s.on_b.x, 2.5, 1e-15);
  EXPECT_NEAR(s.on_b.y - s.on_a.y, 0, 1e-15);  // the closest pairs run along x
  EXPECT_NEAR(s.on_b.z - s.on_a.z, 0, 1e-15);
}

TEST(DistanceObbObb, ApartCornerToCorner) {
  const Separation s = distance_obb_obb(cube({0, 0, 0}), cube({3, 4, 2 + 12}));  // corners (1,1,1), (2,3,13)
  EXPECT_NEAR(s.distance, std::sqrt(1.0 + 4 + 144), s.distance_error);
  expect_vec(s.on_a, {1, 1, 1}, 1e-14);
  expect_vec(s.on_b, {2, 3, 13}, 1e-14);
}

TEST(DistanceObbObb, ApartEdgeToCrossingEdge) {
  // The top edge of a (along y, at z = sqrt 2) and the bottom edge of b (along x) cross 0.25 apart.
  const double gap = 0.25;
  const Separation s =
      distance_obb_obb(cube({0, 0, 0}, 1, edge_up_along_y()), cube({0, 0, 2 * kRoot2 + gap}, 1, edge_down_along_x()));
  EXPECT_NEAR(s.distance, gap, s.distance_error);
  EXPECT_LE(s.distance_error, 1e-12);
  expect_vec(s.on_a, {0, 0, kRoot2}, 1e-14);
  expect_vec(s.on_b, {0, 0, kRoot2 + gap}, 1e-14);
}

TEST(DistanceObbObb, TouchingFacesAreAtZero) {
  const Separation s = distance_obb_obb(cube({0, 0, 0}), cube({2, 0.5, 0.5}));
  EXPECT_NEAR(s.distance, 0, s.distance_error);
  EXPECT_LE(s.distance_error, 1e-12);
}

TEST(DistanceObbObb, OverlappingThroughAFaceIsTheLeastOverlap) {
  // Overlaps of 0.5 on x, 1.8 on y, 2 on z: b is pushed out along +x by 0.5.
  const Separation s = distance_obb_obb(cube({0, 0, 0}), cube({1.5, 0.2, 0}));
  EXPECT_NEAR(s.distance, -0.5, s.distance_error);
  EXPECT_LE(s.distance_error, 1e-12);
  EXPECT_NEAR(s.on_a.x, 1, s.point_error);
  EXPECT_NEAR(s.on_b.x, 0.5, s.point_error);
  expect_vec(s.on_a - s.on_b, {0.5, 0, 0}, 1e-14);
}

// A small box sunk 0.1 into a cube's top face near each of its corners: whichever of the
// face's two triangles it lies over, the witnesses are a meeting pair, 0.1 apart.
TEST(DistanceObbObb, ADepthsWitnessesMeetWhereverOnTheFace) {
  for (const double x : {-0.7, 0.7}) {
    for (const double y : {-0.7, 0.7}) {
      const Obb small{{x, y, 1.9}, {0.25, 0.25, 1}, Mat3::identity()};
      const Separation s = distance_obb_obb(cube({0, 0, 0}), small);
      EXPECT_NEAR(s.distance, -0.1, 1e-12) << x << " " << y;
      EXPECT_NEAR(length(s.on_b - s.on_a), 0.1, 1e-12) << x << " " << y;
      EXPECT_NEAR(s.on_a.z, 1, 1e-12) << x << " " << y;
      EXPECT_LT(s.point_error, 1e-12) << x << " " << y;
    }
  }
}

TEST(DistanceObbObb, OverlappingThroughCrossingEdgesIsTheirDepth) {
  // The crossing edges of ApartEdgeToCrossingEdge pushed 0.1 into each other: the edges' axis (z)
  // is the least; the face axes of both cubes overlap by more than 1.
  const double depth = 0.1;
  const Separation s =
      distance_obb_obb(cube({0, 0, 0}, 1, edge_up_along_y()), cube({0, 0, 2 * kRoot2 - depth}, 1, edge_down_along_x()));
  EXPECT_NEAR(s.distance, -depth, s.distance_error);
  EXPECT_LE(s.distance_error, 1e-12);
  expect_vec(s.on_a, {0, 0, kRoot2}, 1e-13);
  expect_vec(s.on_b, {0, 0, kRoot2 - depth}, 1e-13);
}

TEST(DistanceObbObb, ParallelEdgesKeepTheBoundTight) {
  // The same rotation: every edge of a is parallel to three of b's, whose axes are left out at
  // a sliver of a few ulps.
  const Mat3 r = test::rotation(0.3, -1.1, 0.7);
  const Obb a{{0, 0, 0}, {1, 2, 3}, r};
  for (const double offset : {-0.75, 0.0, 0.75}) {
    const Obb b{r * Vec3{1.5, offset, 0}, {1, 0.5, 0.25}, r};  // overlapping by 0.5 along r's x
    const Separation s = distance_obb_obb(a, b);
    EXPECT_NEAR(s.distance, -0.5, s.distance_error) << offset;
    EXPECT_LE(s.distance_error, 1e-12) << offset;
    const Separation apart = distance_obb_obb(a, {r * Vec3{4, offset, 0}, b.half, r});
    EXPECT_NEAR(apart.distance, 2, apart.distance_error) << offset;
    EXPECT_LE(apart.distance_error, 1e-12) << offset;
  }
}

TEST(DistanceObbObb, FlatBoxesAreTheRectanglesTheyAre) {
  const Obb square{{0, 0, 0}, {1, 1, 0}, Mat3::identity()};
  EXPECT_NEAR(distance_obb_obb(square, {{0, 0, 2}, {1, 1, 0}, Mat3::identity()}).distance, 2, 1e-14);
  // A segment through the square: it must move 0.5 along x to leave it (1 along z), so the depth
  // is 0.5 though neither has an inside.
  const Separation through = distance_obb_obb(square, {{0.5, 0, 0}, {0, 0, 1}, Mat3::identity()});
  EXPECT_NEAR(through.distance, -0.5, through.distance_error);
  EXPECT_LE(through.distance_error, 1e-12);
  // Two squares in one plane, crossing: no translation within the plane is shorter than one
  // across it of length 0, so they touch.
  const Separation flat = distance_obb_obb(square, {{0.5, 0.5, 0}, {1, 1, 0}, Mat3::identity()});
  EXPECT_NEAR(flat.distance, 0, flat.distance_error);
  EXPECT_LE(flat.distance_error, 1e-12);
}

TEST(DistanceObbObb, SwappingGivesTheSameDistance) {
  const Obb a{{0.1, -0.3, 0.2}, {1, 0.5, 2}, test::rotation(0.2, 0.9, -0.4)};
  for (const Vec3& c : {Vec3{2.9, 0.4, 0.1}, Vec3{1.1, -0.2, 0.3}, Vec3{0.2, 0.1, -3.5}, Vec3{0, 0, 0}}) {
    const Obb b{c, {0.7, 1.3, 0.4}, test::rotation(-1.0, 0.35, 2.1)};
    const Separation ab = distance_obb_obb(a, b), ba = distance_obb_obb(b, a);
    EXPECT_NEAR(ab.distance, ba.distance, ab.distance_error + ba.distance_error) << c.x;
    if (ab.distance < 0) {
      EXPECT_EQ(ab.distance, ba.distance) << c.x;  // the same axes, measured alike
    }
  }
}

// The depth is no more than the overlap along any direction, and the distance of boxes apart no
// more than that of any two of their points: checked against directions and points sampled on
// a grid, for boxes drawn at random.
TEST(DistanceObbObb, NeverBeyondAnySampledDirectionOrPair) {
  test::Random random(12345);
  const auto next = [&random] { return random.unit(); };
  int apart = 0, overlapping = 0;
  for (int round = 0; round < 200; ++round) {
    const Obb a{{0, 0, 0}, {0.2 + next(), 0.2 + next(), 0.2 + next()}, test::rotation(6 * next(), 6 * next(), 6 * next())};
    const Obb b{{4 * next() - 2, 4 * next() - 2, 4 * next() - 2},
                {0.2 + next(), 0.2 + next(), 0.2 + next()},
                test::rotation(6 * next(), 6 * next(), 6 * next())};
    const Separation s = distance_obb_obb(a, b);
    ASSERT_TRUE(std::isfinite(s.distance));
    if (s.distance > 0) {
      ++apart;
      // Points of each box on a 5x5x5 grid of its own coordinates.
      double nearest = INFINITY;
      for (int i = 0; i < 125; ++i) {
        const Vec3 u{(i % 5) / 2.0 - 1, (i / 5 % 5) / 2.0 - 1, (i / 25) / 2.0 - 1};
        const Vec3 p = a.center + a.axes * Vec3{u.x * a.half.x, u.y * a.half.y, u.z * a.half.z};
        for (int j = 0; j < 125; ++j) {
          const Vec3 w{(j % 5) / 2.0 - 1, (j / 5 % 5) / 2.0 - 1, (j / 25) / 2.0 - 1};
          const Vec3 q = b.center + b.axes * Vec3{w.x * b.half.x, w.y * b.half.y, w.z * b.half.z};
          nearest = std::min(nearest, std::sqrt(dot(q - p, q - p)));
        }
      }
      EXPECT_LE(s.distance - s.distance_error, nearest + 1e-12) << round;
    } else {
      ++overlapping;
      for (int i = 0; i < 400; ++i) {
        const double z = 2 * next() - 1, phi = 2 * std::numbers::pi * next(), r = std::sqrt(1 - z * z);
        const Vec3 n{r * std::cos(phi), r * std::sin(phi), z};
        double ra = 0, rb = 0;
        for (int k = 0; k < 3; ++k) ra += a.half[k] * std::fabs(dot(a.axes.col[k], n));
        for (int k = 0; k < 3; ++k) rb += b.half[k] * std::fabs(dot(b.axes.col[k], n));
        const double overlap = ra + rb - std::fabs(dot(b.center - a.center, n));
        EXPECT_LE(-s.distance - s.distance_error, overlap + 1e-12) << round;
      }
    }
    // The witnesses' difference is as long as the distance, within the bounds.
    const double apart_by = std::sqrt(dot(s.on_b - s.on_a, s.on_b - s.on_a));
    EXPECT_NEAR(apart_by, std::fabs(s.distance), s.distance_error + 2 * s.point_error + 1e-12) << round;
  }
  EXPECT_GT(apart, 20);
  EXPECT_GT(overlapping, 20);
}

TEST(DistanceObbObb, TinyAndHugeScales) {
  for (const double k : {0x1p-600, 0x1p-300, 0x1p300, 0x1p490}) {
    const Obb a{{0, 0, 0}, {k, k, k}, Mat3::identity()};
    const Separation apart = distance_obb_obb(a, {{3.5 * k, 0, 0}, {k, k, k}, Mat3::identity()});
    EXPECT_NEAR(apart.distance / k, 1.5, 1e-14) << k;
    EXPECT_LE(apart.distance_error / k, 1e-12) << k;
    const Separation deep = distance_obb_obb(a, {{1.5 * k, 0.2 * k, 0}, {k, k, k}, Mat3::identity()});
    EXPECT_NEAR(deep.distance / k, -0.5, 1e-14) << k;
    EXPECT_LE(deep.distance_error / k, 1e-12) << k;
  }
}

TEST(DistanceObbObb, OutsideTheDomainIsNaN) {
  const Obb good = cube({0, 0, 0});
  for (const Obb& bad : {cube({kNan, 0, 0}), cube({0, 0, 0}, -1), cube({HUGE_VAL, 0, 0})}) {
    const Separation s = distance_obb_obb(bad, good);
    EXPECT_TRUE(std::isnan(s.distance));
    EXPECT_TRUE(std::isinf(s.distance_error));
    EXPECT_TRUE(std::isnan(distance_obb_obb(good, bad).distance));
  }
}

}  // namespace
}  // namespace cc
