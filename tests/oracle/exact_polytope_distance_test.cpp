// exact_polytope_distance on boxes whose signed distances are known: apart, touching, overlapping
// through a face and through crossing edges, nested, flat ones (a segment through a square, two
// squares in one plane), points; and, for boxes drawn at random, apart ones against the least over
// their feature pairs (each corner against the other box, each pair of edges), which reaches the
// same number by another road.
#include "oracle/exact/exact_polytope_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "oracle/exact/exact_distance.h"
#include "rotations.h"
#include "test_random.h"

namespace cc::exact {
namespace {

Obb box(const Vec3& center, const Vec3& half, const Mat3& axes = Mat3::identity()) { return {center, half, axes}; }

ExactSignedDistance between(const Obb& a, const Obb& b) {
  const auto ca = box_corners(a), cb = box_corners(b);
  return exact_polytope_distance(ca, cb);
}

void expect_signed(const ExactSignedDistance& d, int sign, const Rational& squared) {
  EXPECT_EQ(d.squared, squared) << d.squared.get_d();
  if (sgn(squared) != 0) {
    EXPECT_EQ(d.sign, sign);
  }
  EXPECT_EQ(d.reach, 0);
}

TEST(ExactPolytopeDistance, CornersAreTheBoxsCorners) {
  const auto c = box_corners(box({1, 2, 3}, {0.5, 1, 2}));
  EXPECT_EQ(c[0].x, Rational(1, 2));  // all minus
  EXPECT_EQ(c[0].z, 1);
  EXPECT_EQ(c[7].y, 3);  // all plus
  EXPECT_EQ(c[1].x, Rational(3, 2));  // bit 0: +x
}

TEST(ExactPolytopeDistance, ApartTouchingOverlapping) {
  const Obb unit = box({0, 0, 0}, {1, 1, 1});
  expect_signed(between(unit, box({3.5, 0.25, -0.5}, {1, 1, 1})), 1, Rational(9, 4));  // 1.5 apart
  expect_signed(between(unit, box({3, 4, 14}, {1, 1, 1})), 1, 1 + 4 + 144);            // corner to corner
  expect_signed(between(unit, box({2, 0.5, 0.5}, {1, 1, 1})), 1, 0);                   // touching faces
  expect_signed(between(unit, box({1.5, 0.2, 0}, {1, 1, 1})), -1, Rational(1, 4));     // 0.5 deep along x
  // Nested: the small box must move 1 + 0.25 - 0.5 along x to leave (its nearest face is 0.5 away).
  expect_signed(between(unit, box({0.5, 0, 0}, {0.25, 0.25, 0.25})), -1, Rational(9, 16));
}

TEST(ExactPolytopeDistance, CrossingEdgesAreTheirDepthApart) {
  // Two unit cubes turned 45 degrees (about y and about x), their edges crossing: depth along z.
  // The rotations are rounded, so the squares are compared after rounding.
  const Obb a = box({0, 0, 0}, {1, 1, 1}, test::rotation(0, 0, std::numbers::pi / 4));
  for (const double gap : {0.25, -0.125}) {
    const Obb b = box({0, 0, 2 * std::numbers::sqrt2 + gap}, {1, 1, 1}, test::rotation(std::numbers::pi / 4, 0, 0));
    const ExactSignedDistance d = between(a, b);
    EXPECT_EQ(d.sign, gap > 0 ? 1 : -1);
    EXPECT_NEAR(std::sqrt(d.squared.get_d()), std::fabs(gap), 1e-15);
  }
}

TEST(ExactPolytopeDistance, FlatShapesAndPoints) {
  const Obb square = box({0, 0, 0}, {1, 1, 0});
  expect_signed(between(square, box({0.5, 0, 0}, {0, 0, 1})), -1, Rational(1, 4));  // a segment through it
  expect_signed(between(square, box({0.5, 0.5, 0}, {1, 1, 0})), 1, 0);              // crossing in one plane
  expect_signed(between(square, box({3.5, 0.5, 0}, {1, 1, 0})), 1, Rational(9, 4));  // apart in one plane
  expect_signed(between(square, box({0, 0, 2}, {1, 1, 0})), 1, 4);                   // parallel planes
  expect_signed(between(box({0, 0, 0}, {0, 0, 0}), box({3, 4, 0}, {0, 0, 0})), 1, 25);  // two points
  expect_signed(between(box({0, 0, 0}, {1, 0, 0}), box({3, 4, 0}, {1, 0, 0})), 1, 17);  // parallel segments
}

// The least over feature pairs: each corner against the other box, each pair of edges.
Rational feature_pairs(const Obb& a, const Obb& b) {
  const auto ca = box_corners(a), cb = box_corners(b);
  Rational least = squared_distance_to_box(ca[0], b);
  for (int i = 0; i < 8; ++i) {
    least = std::min({least, squared_distance_to_box(ca[i], b), squared_distance_to_box(cb[i], a)});
  }
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 8; ++i) {
      if (i >> k & 1) continue;
      for (int l = 0; l < 3; ++l) {
        for (int j = 0; j < 8; ++j) {
          if (j >> l & 1) continue;
          // The segments' distance, from their rational ends, by the closest-point formula of the
          // triangles' reference (a degenerate triangle is its segment).
          const Rational d = squared_distance_between_triangles(QTriangle{ca[i], ca[i | 1 << k], ca[i | 1 << k]},
                                                                QTriangle{cb[j], cb[j | 1 << l], cb[j | 1 << l]});
          least = std::min(least, d);
        }
      }
    }
  }
  return least;
}

TEST(ExactPolytopeDistance, ApartItIsTheLeastOverFeaturePairs) {
  test::Random random(99);
  const auto next = [&random] { return random.unit(); };
  int apart = 0, overlapping = 0;
  for (int round = 0; round < 40; ++round) {
    const Obb a = box({0, 0, 0}, {0.2 + next(), 0.2 + next(), 0.2 + next()}, test::rotation(6 * next(), 6 * next(), 6 * next()));
    const Obb b = box({4 * next() - 2, 4 * next() - 2, 4 * next() - 2}, {0.2 + next(), 0.2 + next(), next() < 0.2 ? 0 : 0.5},
                      test::rotation(6 * next(), 6 * next(), 6 * next()));
    const ExactSignedDistance d = between(a, b);
    if (d.sign > 0 && sgn(d.squared) > 0) {
      ++apart;
      EXPECT_EQ(d.squared, feature_pairs(a, b)) << round;
    } else {
      ++overlapping;
      // The depth is at most the overlap of the projections on any axis: on each box's axes.
      for (const Obb* box : {&a, &b}) {
        for (int k = 0; k < 3; ++k) {
          const QVec3 n = rational(box->axes.col[k]);
          Rational reach = 0;
          for (const Obb* other : {&a, &b}) {
            for (int j = 0; j < 3; ++j) reach += rational(other->half[j]) * abs(dot(rational(other->axes.col[j]), n));
          }
          const Rational overlap = reach - abs(dot(rational(b.center) - rational(a.center), n));
          EXPECT_LE(d.squared * dot(n, n), overlap * overlap) << round;
        }
      }
    }
  }
  EXPECT_GT(apart, 10);
  EXPECT_GT(overlapping, 5);
}

}  // namespace
}  // namespace cc::exact
