#include "collide/moving_box.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "oracle/exact/exact_sweep.h"
#include "oracle/exact/rational.h"

namespace cc {
namespace {

using exact::QVec3;
using exact::Rational;

const double kNan = std::numeric_limits<double>::quiet_NaN();

Obb box(Vec3 center, Vec3 half, Mat3 axes = Mat3::identity()) { return {center, half, axes}; }
MovingObb moving(const Obb& b, Vec3 velocity) { return {b, velocity}; }

Mat3 about_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Mat3::from_columns({c, s, 0}, {-s, c, 0}, {0, 0, 1});
}

const Obb kUnit = box({0, 0, 0}, {1, 1, 1});
const Aabb kUnitAabb{{-1, -1, -1}, {1, 1, 1}};

// The box at time t (its centre moved in floating point).
Obb at(const MovingObb& m, double t) { return {m.box.center + t * m.velocity, m.box.half, m.box.axes}; }
Aabb at(const Aabb& b, const Vec3& velocity, double t) { return {b.lo + t * velocity, b.hi + t * velocity}; }

// The tolerance of sweep_obb_obb: 2^-40 of the largest coordinate of centres, velocities and
// half extents.
double band(const MovingObb& a, const MovingObb& b) {
  return 0x1p-40 * std::max({max_abs(a.box.center), max_abs(a.velocity), max_abs(a.box.half),
                             max_abs(b.box.center), max_abs(b.velocity), max_abs(b.box.half)});
}

bool same_bits(const SweepHit& x, const SweepHit& y) {
  return x.hit == y.hit && std::bit_cast<std::uint64_t>(x.t_first) == std::bit_cast<std::uint64_t>(y.t_first) &&
         std::bit_cast<std::uint64_t>(x.t_last) == std::bit_cast<std::uint64_t>(y.t_last);
}

// ---- Exact references (GMP rationals), for boxes with positive extents ----

using exact::ExactWindow;

// The boxes as the parallelepipeds they are (axes as given, not quite orthonormal).
ExactWindow exact_sweep(const MovingObb& a, const MovingObb& b) { return exact::exact_sweep(exact::moving_axes(a, b)); }

// The largest gap between the boxes at time t over the 15 axes a_i, b_j, a_i x b_j as given
// (not normalised).
Rational largest_gap(const MovingObb& a, const MovingObb& b, const Rational& t) {
  std::vector<QVec3> axes_a, axes_b, axes;
  for (int i = 0; i < 3; ++i) axes_a.push_back(exact::rational(a.box.axes.col[i]));
  for (int i = 0; i < 3; ++i) axes_b.push_back(exact::rational(b.box.axes.col[i]));
  axes = axes_a;
  axes.insert(axes.end(), axes_b.begin(), axes_b.end());
  for (const QVec3& x : axes_a) {
    for (const QVec3& y : axes_b) axes.push_back(exact::cross(x, y));
  }
  const QVec3 d = exact::rational(b.box.center) - exact::rational(a.box.center) +
                  t * (exact::rational(b.velocity) - exact::rational(a.velocity));
  Rational largest = -1;
  for (const QVec3& n : axes) {
    Rational gap = abs(exact::dot(n, d));
    for (int i = 0; i < 3; ++i) gap -= exact::rational(a.box.half[i]) * abs(exact::dot(n, axes_a[i]));
    for (int i = 0; i < 3; ++i) gap -= exact::rational(b.box.half[i]) * abs(exact::dot(n, axes_b[i]));
    largest = std::max(largest, gap);
  }
  return largest;
}

ExactWindow exact_sweep(const Aabb& a, const Vec3& va, const Aabb& b, const Vec3& vb) {
  return exact::exact_sweep(a, va, b, vb);
}

// ---- Random cases (deterministic: the generator's bits, not a distribution's) ----

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * (static_cast<double>(engine_() >> 11) * 0x1p-53); }
  int below(int n) { return static_cast<int>(engine_() % static_cast<std::uint64_t>(n)); }
  Vec3 vec(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
  Mat3 rotation() {  // from a random unit quaternion; orthonormal to within a few ulps
    double w, x, y, z, n;
    do {
      w = uniform(-1, 1), x = uniform(-1, 1), y = uniform(-1, 1), z = uniform(-1, 1);
      n = std::sqrt(w * w + x * x + y * y + z * z);
    } while (n < 0.1);
    w /= n, x /= n, y /= n, z /= n;
    return Mat3::from_columns({1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
                              {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
                              {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)});
  }
  // Two moving boxes near each other; sometimes axis-aligned, sometimes with equal velocities or
  // velocity components (rates exactly 0).
  std::pair<MovingObb, MovingObb> obb_pair() {
    MovingObb a{box(vec(-1, 1), vec(0.05, 1.5), below(4) == 0 ? Mat3::identity() : rotation()), vec(-3, 3)};
    MovingObb b{box(vec(-3, 3), vec(0.05, 1.5), below(4) == 0 ? Mat3::identity() : rotation()), vec(-3, 3)};
    if (below(8) == 0) b.velocity = a.velocity;
    if (below(4) == 0) {
      const int k = below(3);
      b.velocity[k] = a.velocity[k];
    }
    return {a, b};
  }

 private:
  std::mt19937_64 engine_;
};

struct AabbCase {
  Aabb a;
  Vec3 va;
  Aabb b;
  Vec3 vb;
};

AabbCase random_aabb_case(Random& rng) {
  const auto random_box = [&rng](double reach) {
    const Vec3 c = rng.vec(-reach, reach), h = rng.vec(0, 1.5);
    return Aabb{c - h, c + h};
  };
  AabbCase c{random_box(1), rng.vec(-3, 3), random_box(4), rng.vec(-3, 3)};
  if (rng.below(4) == 0) {
    const int k = rng.below(3);
    c.vb[k] = c.va[k];
  }
  return c;
}

// ---- Oriented boxes ----

// A flat box sliding past a segment with a gap that an edge axis shows. A velocity component of
// 1e-36 makes that axis's rate tiny in a's frame and rounding noise in b's: both windows lie far
// outside the step, one before it and one after. They must not join into a window over the
// whole step (found by the moving_obb campaign; corpora/moving_obb holds the case).
TEST(SweepObbObb, EdgeAxisWindowsOnBothSidesOfTheStepStillSeparate) {
  const MovingObb a{box({0, 0, 0}, {0, 26.606477512214493, 0}, Mat3::from_columns({0, 1, 0}, {1, 0, 0}, {0, 0, 1})), {}};
  const MovingObb b{box({13.303238756107246, 0, 0.9033384755451381}, {0, 1, 0.01638648348841674},
                        Mat3::from_columns({-0.3001622110843649, -0.9260882935914774, -0.22861128473846437},
                                           {-0.30438780844723085, 0.32012404029013497, -0.8971447268401082},
                                           {0.9040191973103434, -0.19970245692315813, -0.37797912586969273})),
                    {5.905502822676008, 1.504632769052528e-36, -5e-324}};
  ASSERT_FALSE(exact_sweep(a, b).hit());
  EXPECT_FALSE(sweep_obb_obb(a, b).hit);
  EXPECT_FALSE(sweep_obb_obb(b, a).hit);
}

TEST(SweepObbObb, HeadOnApproachMeetsAtTheKnownTime) {
  // Half extents 1, centres 3 apart, closing at 4: the faces meet at t = (3 - 2) / 4 = 1/4 and the
  // boxes overlap until t = 5/4, past the step.
  const MovingObb a = moving(kUnit, {0, 0, 0}), b = moving(box({3, 0, 0}, {1, 1, 1}), {-4, 0, 0});
  const SweepHit h = sweep_obb_obb(a, b);
  EXPECT_TRUE(h.hit);
  EXPECT_LE(h.t_first, 0.25);
  EXPECT_GE(h.t_first, 0.25 - band(a, b) / 4);
  EXPECT_EQ(h.t_last, 1);
  // Only the relative velocity counts.
  const SweepHit split = sweep_obb_obb(moving(kUnit, {1, 0, 0}), moving(box({3, 0, 0}, {1, 1, 1}), {-3, 0, 0}));
  EXPECT_TRUE(split.hit);
  EXPECT_LE(split.t_first, 0.25);
  EXPECT_GE(split.t_first, 0.25 - band(a, b) / 4);
  // Closing at 3 instead: t = 1/3, which no double equals; t_first <= 1/3 means t_first <= the
  // double below it, 1.0 / 3.
  const MovingObb c = moving(box({3, 0, 0}, {1, 1, 1}), {-3, 0, 0});
  const SweepHit third = sweep_obb_obb(a, c);
  EXPECT_TRUE(third.hit);
  EXPECT_LE(third.t_first, 1.0 / 3);
  EXPECT_GE(third.t_first, 1.0 / 3 - band(a, c) / 3);
}

TEST(SweepObbObb, PassingByWithoutTouchingIsAMiss) {
  const MovingObb a = moving(kUnit, {0, 0, 0});
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({-6, 2.5, 0}, {1, 1, 1}), {16, 0, 0})).hit);   // beside
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({-6, 2, 2.5}, {1, 1, 1}), {16, 0, 0})).hit);   // above an edge
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({-6, 0, 0}, {1, 1, 1}), {-16, 0, 0})).hit);    // moving away
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({-6, 0, 0}, {1, 1, 1}), {3.99, 0, 0})).hit);  // stops short
}

TEST(SweepObbObb, MotionParallelToAFaceIsDecidedStaticallyOnThatAxis) {
  // b slides along x with its face in the plane y = 1 of a's face: the rate on y is exactly 0
  // and the static criterion keeps the touching faces. On x, -6 + 16 t in [-2, 2]: [1/4, 1/2].
  const MovingObb a = moving(kUnit, {0, 0, 0}), b = moving(box({-6, 2, 0}, {1, 1, 1}), {16, 0, 0});
  const SweepHit h = sweep_obb_obb(a, b);
  EXPECT_TRUE(h.hit);
  EXPECT_LE(h.t_first, 0.25);
  EXPECT_GE(h.t_first, 0.25 - band(a, b) / 16);
  EXPECT_GE(h.t_last, 0.5);
  EXPECT_LE(h.t_last, 0.5 + band(a, b) / 16);
  // The same slide 1e-9 away from the face (far beyond the band, 2^-40 * 16): no hit.
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({-6, 2 + 1e-9, 0}, {1, 1, 1}), {16, 0, 0})).hit);
}

TEST(SweepObbObb, TouchingExactlyAtTheEndOfTheStepIsAHit) {
  const MovingObb a = moving(kUnit, {0, 0, 0}), b = moving(box({4, 0, 0}, {1, 1, 1}), {-2, 0, 0});
  const SweepHit h = sweep_obb_obb(a, b);
  EXPECT_TRUE(h.hit);
  EXPECT_LE(h.t_first, 1);
  EXPECT_GE(h.t_first, 1 - band(a, b) / 2);
  EXPECT_EQ(h.t_last, 1);
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({4 + 1e-9, 0, 0}, {1, 1, 1}), {-2, 0, 0})).hit);
}

TEST(SweepObbObb, TouchingAtTheStartOfTheStepIsAHitAtZero) {
  const MovingObb a = moving(kUnit, {0, 0, 0}), b = moving(box({2, 0, 0}, {1, 1, 1}), {1, 0, 0});  // leaving
  const SweepHit h = sweep_obb_obb(a, b);
  EXPECT_TRUE(h.hit);
  EXPECT_EQ(h.t_first, 0);
  EXPECT_GE(h.t_last, 0);
  EXPECT_LE(h.t_last, band(a, b));
  // Corner to corner, leaving diagonally.
  EXPECT_EQ(sweep_obb_obb(a, moving(box({2, 2, 2}, {1, 1, 1}), {1, 1, 1})).t_first, 0);
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({2 + 1e-9, 0, 0}, {1, 1, 1}), {1, 0, 0})).hit);
}

TEST(SweepObbObb, AlreadyOverlappingStartsAtZero) {
  // b (turned by 0.3) reaches about 1.25 along x: it leaves the overlap at t = 0.11 or so.
  const MovingObb a = moving(kUnit, {0, 0, 0}), b = moving(box({0.5, 0.5, 0}, {1, 1, 1}, about_z(0.3)), {16, 0, 0});
  const SweepHit h = sweep_obb_obb(a, b);
  EXPECT_TRUE(h.hit);
  EXPECT_EQ(h.t_first, 0);
  EXPECT_GT(h.t_last, 0);
  EXPECT_LT(h.t_last, 0.5);
  // Staying inside all step long.
  const SweepHit inside = sweep_obb_obb(a, moving(box({0, 0, 0}, {0.25, 0.25, 0.25}), {0.5, 0.5, 0}));
  EXPECT_TRUE(inside.hit);
  EXPECT_EQ(inside.t_first, 0);
  EXPECT_EQ(inside.t_last, 1);
  // Static agreement where the boxes are at t_last: still touching (up to the band).
  EXPECT_LE(largest_gap(a, b, exact::rational(h.t_last)), exact::rational(band(a, b)));
}

TEST(SweepObbObb, ZeroRelativeVelocityIsTheStaticTest) {
  const Mat3 tilt = about_z(1e-15), r = about_z(M_PI / 4);
  const std::vector<std::pair<Obb, Obb>> pairs = {
      {kUnit, box({2, 0, 0}, {1, 1, 1})},                            // face contact
      {kUnit, box({2, 2, 2}, {1, 1, 1})},                            // corner contact
      {kUnit, box({2 + 1e-9, 0, 0}, {1, 1, 1})},                     // apart
      {kUnit, box({1 + std::sqrt(2.0) + 1e-9, 0, 0}, {1, 1, 1}, r)},  // apart, rotated
      {kUnit, box({1 + std::sqrt(2.0) - 1e-9, 0, 0}, {1, 1, 1}, r)},  // overlapping, rotated
      {kUnit, box({1.5, 1.5, 0}, {1, 1, 1}, tilt)},                  // nearly parallel edges
      {kUnit, box({2.5, 0, 0}, {1, 1, 1}, tilt)},
      {box({0, 0, 0}, {1, 0, 0}), box({0, 0.5, 0}, {1, 0, 0})},      // parallel segments apart
      {kUnit, box({1, 0.5, 0}, {0, 0, 0})},                          // a point on a face
  };
  for (const auto& [p, q] : pairs) {
    for (const Vec3 velocity : {Vec3{0, 0, 0}, Vec3{1, -2, 0.5}}) {
      const SweepHit h = sweep_obb_obb(moving(p, velocity), moving(q, velocity));
      EXPECT_EQ(h.hit, test_obb_obb(p, q));
      if (h.hit) {
        EXPECT_EQ(h.t_first, 0);
        EXPECT_EQ(h.t_last, 1);
      }
    }
  }
}

// b is a cube turned so that one of its edges, along (1, -1, 0), lies across a's vertical edge at
// x = y = 1, the two edges `gap` apart along their common normal n = (1, 1, 0) / sqrt(2). For a
// small gap no face axis separates (their gaps are about -0.4 or less); only a_z x b_x does.
MovingObb crossed_edges(double gap, Vec3 velocity) {
  const double s = std::sqrt(0.5);
  const Mat3 axes = Mat3::from_columns({s, -s, 0}, {0.5, 0.5, s}, {-0.5, -0.5, s});
  return moving(box({2 + gap * s, 2 + gap * s, 0}, {1, 1, 1}, axes), velocity);
}

// The largest gap over the six face axes (normalised), in double precision: for checking that
// the face axes do not separate.
double largest_face_gap(const Obb& a, const Obb& b) {
  double largest = -INFINITY;
  for (const Mat3* frame : {&a.axes, &b.axes}) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 n = frame->col[k];
      double gap = std::fabs(dot(n, b.center - a.center));
      for (int i = 0; i < 3; ++i) gap -= a.half[i] * std::fabs(dot(n, a.axes.col[i])) + b.half[i] * std::fabs(dot(n, b.axes.col[i]));
      largest = std::max(largest, gap);
    }
  }
  return largest;
}

TEST(SweepObbObb, OnlyAnEdgeEdgeAxisSeparatesOverTheWholeStep) {
  const MovingObb a = moving(kUnit, {0, 0, 0});
  const Vec3 along_both_edges{0.3, -0.3, 0.4};  // perpendicular to n: the gap stays 0.01
  const MovingObb b = crossed_edges(0.01, along_both_edges);
  for (double t : {0.0, 0.5, 1.0}) {
    EXPECT_LT(largest_face_gap(at(a, t), at(b, t)), -0.3) << t;
    EXPECT_FALSE(test_obb_obb(at(a, t), at(b, t))) << t;
  }
  EXPECT_FALSE(sweep_obb_obb(a, b).hit);
  EXPECT_FALSE(sweep_obb_obb(b, a).hit);
  // The edges 0.01 into each other instead: a hit all step long.
  const SweepHit through = sweep_obb_obb(a, crossed_edges(-0.01, along_both_edges));
  EXPECT_TRUE(through.hit);
  EXPECT_EQ(through.t_first, 0);
  EXPECT_EQ(through.t_last, 1);
  // Closing along n at 0.02: the edge axis alone decides the first contact, at t = 1/2.
  const double s = std::sqrt(0.5);
  const MovingObb closing = crossed_edges(0.01, along_both_edges - Vec3{0.02 * s, 0.02 * s, 0});
  const SweepHit h = sweep_obb_obb(a, closing);
  EXPECT_TRUE(h.hit);
  EXPECT_NEAR(h.t_first, 0.5, 1e-9);
  EXPECT_EQ(h.t_last, 1);
  const ExactWindow exact = exact_sweep(a, closing);
  EXPECT_LE(exact::rational(h.t_first), exact.first);
  EXPECT_LT(largest_face_gap(at(a, h.t_first), at(closing, h.t_first)), -0.3);
}

TEST(SweepObbObb, PerAxisWindowsThatNeverMeetAreAMiss) {
  // b's centre runs from (-4, 1) to (1, 6) past the corner of [-2, 2]^2, the Minkowski square:
  // x overlaps for t in [0.4, 1.2], y for t in [-0.6, 0.2], z always; never all three at once.
  const MovingObb a = moving(kUnit, {0, 0, 0}), b = moving(box({-4, 1, 0}, {1, 1, 1}), {5, 5, 0});
  const auto overlaps_on = [&](int axis, double t) { return std::fabs(at(b, t).center[axis]) <= 2; };
  EXPECT_TRUE(overlaps_on(1, 0.1) && !overlaps_on(0, 0.1));
  EXPECT_TRUE(overlaps_on(0, 0.5) && !overlaps_on(1, 0.5));
  EXPECT_FALSE(sweep_obb_obb(a, b).hit);
  // One unit lower the path runs through the corner at t = 0.4: x in [0.4, 1.2], y in [-0.4, 0.4].
  const MovingObb through_corner = moving(box({-4, 0, 0}, {1, 1, 1}), {5, 5, 0});
  const SweepHit h = sweep_obb_obb(a, through_corner);
  EXPECT_TRUE(h.hit);
  EXPECT_LE(h.t_first, 0.4);
  EXPECT_GE(h.t_last, 0.4);
  EXPECT_LE(h.t_last - h.t_first, 2 * band(a, through_corner) / 5);
}

TEST(SweepObbObb, NearlyParallelEdgesNeitherSeparateFalselyNorHideASeparation) {
  const Mat3 tilt = about_z(1e-15);
  const MovingObb a = moving(kUnit, {0, 0, 0});
  // Closing along x on a box turned by 1e-15: first contact at t = 1/2 (to within 1e-15).
  const SweepHit closing = sweep_obb_obb(a, moving(box({2.5, 0, 0}, {1, 1, 1}, tilt), {-1, 0, 0}));
  EXPECT_TRUE(closing.hit);
  EXPECT_NEAR(closing.t_first, 0.5, 1e-9);
  // Sliding along y half a unit beside a's face: the x face axis separates all step long.
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({2.5, -5, 0}, {1, 1, 1}, tilt), {0, 10, 0})).hit);
  // Long thin boxes side by side, overlapping in y, sliding along their length.
  const SweepHit thin = sweep_obb_obb(moving(box({0, 0, 0}, {100, 0.001, 0.001}), {0, 0, 0}),
                                      moving(box({0, 0.0015, 0}, {100, 0.001, 0.001}, tilt), {50, 0, 0}));
  EXPECT_TRUE(thin.hit);
  EXPECT_EQ(thin.t_first, 0);
  EXPECT_EQ(thin.t_last, 1);
}

TEST(SweepObbObb, ZeroExtentsArePointsAndSegments) {
  const MovingObb a = moving(kUnit, {0, 0, 0});
  // A point crossing the box: it enters the face x = -1 at t = 1/2 and reaches x = 1 at t = 1.
  const MovingObb point = moving(box({-3, 0.5, 0.5}, {0, 0, 0}), {4, 0, 0});
  const SweepHit h = sweep_obb_obb(a, point);
  EXPECT_TRUE(h.hit);
  EXPECT_LE(h.t_first, 0.5);
  EXPECT_GE(h.t_first, 0.5 - band(a, point) / 4);
  EXPECT_EQ(h.t_last, 1);
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({-3, 1.5, 0.5}, {0, 0, 0}), {4, 0, 0})).hit);
  // Two crossed segments, one falling onto the other: they touch at t = 1/2 only.
  const MovingObb lying = moving(box({0, 0, 0}, {1, 0, 0}), {0, 0, 0});
  const MovingObb falling = moving(box({0, 0, 2}, {0, 1, 0}), {0, 0, -4});
  const SweepHit cross = sweep_obb_obb(lying, falling);
  EXPECT_TRUE(cross.hit);
  EXPECT_LE(cross.t_first, 0.5);
  EXPECT_GE(cross.t_last, 0.5);
  EXPECT_LE(cross.t_last - cross.t_first, 2 * band(lying, falling) / 4);
  // The same fall beside the other segment's end.
  EXPECT_FALSE(sweep_obb_obb(lying, moving(box({1.5, 0, 2}, {0, 1, 0}), {0, 0, -4})).hit);
}

TEST(SweepObbObb, IsSymmetricBitForBit) {
  Random rng(1);
  for (int n = 0; n < 2000; ++n) {
    const auto [a, b] = rng.obb_pair();
    EXPECT_TRUE(same_bits(sweep_obb_obb(a, b), sweep_obb_obb(b, a))) << n;
  }
}

// Sampled static tests over 64 steps: whenever test_obb_obb reports contact at a sampled t, the
// sweep hits with t in [t_first, t_last]. At t_first and t_last the static test reports contact
// for the boxes grown by 2^-30 M (a margin far above the band; growing does not widen the edge
// axes of nearly parallel edges, which random frames almost never have).
TEST(SweepObbObb, AgreesWithSampledStaticTests) {
  Random rng(2);
  int hits = 0, misses = 0;
  for (int n = 0; n < 2000; ++n) {
    const auto [a, b] = rng.obb_pair();
    const SweepHit h = sweep_obb_obb(a, b);
    (h.hit ? hits : misses) += 1;
    for (int k = 0; k <= 64; ++k) {
      const double t = k / 64.0;
      if (!test_obb_obb(at(a, t), at(b, t))) continue;
      ASSERT_TRUE(h.hit) << n << " t=" << t;
      EXPECT_LE(h.t_first, t) << n;
      EXPECT_GE(h.t_last, t) << n;
    }
    if (!h.hit) continue;
    const double grow = 0x1p-30 * band(a, b) * 0x1p40;
    const auto grown = [grow](Obb o) {
      o.half = o.half + Vec3{grow, grow, grow};
      return o;
    };
    EXPECT_TRUE(test_obb_obb(grown(at(a, h.t_first)), grown(at(b, h.t_first)))) << n;
    EXPECT_TRUE(test_obb_obb(grown(at(a, h.t_last)), grown(at(b, h.t_last)))) << n;
  }
  EXPECT_GT(hits, 400);  // the cases exercise both answers
  EXPECT_GT(misses, 400);
}

// Against exact rational arithmetic on the boxes as given: every exact contact is a hit, with
// t_first <= the exact first contact time and t_last >= the exact last; and at t_first and
// t_last no axis separates the boxes by more than the band.
TEST(SweepObbObb, IsConservativeAndWithinTheBandInExactArithmetic) {
  Random rng(3);
  int exact_hits = 0;
  for (int n = 0; n < 1000; ++n) {
    const auto [a, b] = rng.obb_pair();
    const SweepHit h = sweep_obb_obb(a, b);
    const ExactWindow exact = exact_sweep(a, b);
    if (exact.hit()) {
      ++exact_hits;
      ASSERT_TRUE(h.hit) << n;
      EXPECT_LE(exact::rational(h.t_first), exact.first) << n;
      EXPECT_GE(exact::rational(h.t_last), exact.last) << n;
    }
    if (h.hit) {
      const Rational tolerance = exact::rational(band(a, b));
      EXPECT_LE(largest_gap(a, b, exact::rational(h.t_first)), tolerance) << n;
      EXPECT_LE(largest_gap(a, b, exact::rational(h.t_last)), tolerance) << n;
    }
  }
  EXPECT_GT(exact_hits, 200);
}

// Grazing contacts, found by bisection on one coordinate of b's centre or velocity between an
// exact hit and an exact miss: the last double that still meets (exactly) must be a hit, with
// t_first and t_last on the conservative side of the exact ones.
TEST(SweepObbObb, GrazingContactsFoundByBisectionAreHits) {
  Random rng(9);
  int grazes = 0;
  for (int n = 0; n < 200 && grazes < 40; ++n) {
    const auto [a, b] = rng.obb_pair();
    if (!exact_sweep(a, b).hit()) continue;
    const int k = rng.below(3);
    const bool on_velocity = rng.below(2) == 1;
    const auto with = [&, b = b](double x) {
      MovingObb m = b;
      (on_velocity ? m.velocity : m.box.center)[k] = x;
      return m;
    };
    double meets = on_velocity ? b.velocity[k] : b.box.center[k];
    double misses = meets + (rng.below(2) == 1 ? 20 : -20);
    if (exact_sweep(a, with(misses)).hit()) continue;
    for (double mid = meets + (misses - meets) / 2; mid != meets && mid != misses; mid = meets + (misses - meets) / 2) {
      (exact_sweep(a, with(mid)).hit() ? meets : misses) = mid;
    }
    ++grazes;
    const MovingObb grazing = with(meets);
    const SweepHit h = sweep_obb_obb(a, grazing);
    const ExactWindow exact = exact_sweep(a, grazing);
    ASSERT_TRUE(h.hit) << n;
    EXPECT_LE(exact::rational(h.t_first), exact.first) << n;
    EXPECT_GE(exact::rational(h.t_last), exact.last) << n;
    EXPECT_TRUE(same_bits(h, sweep_obb_obb(grazing, a))) << n;
  }
  EXPECT_GE(grazes, 20);
}

TEST(SweepObbObb, OutOfContractInputsGiveNoHit) {
  const MovingObb a = moving(kUnit, {0, 0, 0});
  const Obb near = box({1, 0, 0}, {1, 1, 1});
  ASSERT_TRUE(sweep_obb_obb(a, moving(near, {0, 0, 0})).hit);
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({kNan, 0, 0}, {1, 1, 1}), {0, 0, 0})).hit);
  EXPECT_FALSE(sweep_obb_obb(a, moving(near, {kNan, 0, 0})).hit);
  EXPECT_FALSE(sweep_obb_obb(a, moving(near, {0, kNan, 0})).hit);
  EXPECT_FALSE(sweep_obb_obb(moving(kUnit, {0, 0, kNan}), moving(near, {0, 0, 0})).hit);
  EXPECT_FALSE(sweep_obb_obb(a, moving(near, {INFINITY, 0, 0})).hit);
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({INFINITY, 0, 0}, {1, 1, 1}), {-INFINITY, 0, 0})).hit);
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({1, 0, 0}, {kNan, 1, 1}), {0, 0, 0})).hit);
  EXPECT_FALSE(sweep_obb_obb(a, moving(box({1, 0, 0}, {-1, 1, 1}), {0, 0, 0})).hit);
  EXPECT_FALSE(
      sweep_obb_obb(a, moving(box({1, 0, 0}, {1, 1, 1}, Mat3::from_columns({1, 0, 0}, {0, kNan, 0}, {0, 0, 1})), {})).hit);
  EXPECT_EQ(sweep_obb_obb(a, moving(near, {kNan, 0, 0})), SweepHit{});
}

// ---- Axis-aligned boxes ----

TEST(SweepAabbAabb, HeadOnApproachMeetsAtTheExactTime) {
  const Aabb b{{2, -1, -1}, {4, 1, 1}};
  const SweepHit h = sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, b, {-4, 0, 0});
  EXPECT_TRUE(h.hit);
  EXPECT_EQ(h.t_first, 0.25);  // (1 - 2) / (-4): both differences and the quotient exact
  EXPECT_EQ(h.t_last, 1);
  EXPECT_EQ(sweep_aabb_aabb(kUnitAabb, {1, 0, 0}, b, {-3, 0, 0}), h);
  // 1/3 is not a double: t_first is at most 1.0 / 3, the double below it, and within 2^-49.
  const SweepHit third = sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, b, {-3, 0, 0});
  EXPECT_TRUE(third.hit);
  EXPECT_LE(third.t_first, 1.0 / 3);
  EXPECT_GE(third.t_first, 1.0 / 3 - 0x1p-49);
}

TEST(SweepAabbAabb, PassingByWithoutTouchingIsAMiss) {
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{-7, 1.5, -1}, {-5, 3.5, 1}}, {16, 0, 0}).hit);
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{-7, -1, -1}, {-5, 1, 1}}, {-16, 0, 0}).hit);
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{-7, -1, -1}, {-5, 1, 1}}, {3.99, 0, 0}).hit);
}

TEST(SweepAabbAabb, MotionParallelToAFaceIsDecidedExactlyOnThatAxis) {
  // Sliding along x with the faces y = 1 touching: on x, -6 + 16 t in [-2, 2], [1/4, 1/2].
  const SweepHit h = sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{-7, 1, -1}, {-5, 3, 1}}, {16, 0, 0});
  EXPECT_TRUE(h.hit);
  EXPECT_EQ(h.t_first, 0.25);
  EXPECT_EQ(h.t_last, 0.5);
  // One ulp off the face: no hit, exactly. Equal nonzero y velocities are a rate of 0 as well.
  const double next = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{-7, next, -1}, {-5, 3, 1}}, {16, 0, 0}).hit);
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0.1, 0}, {{-7, next, -1}, {-5, 3, 1}}, {16, 0.1, 0}).hit);
  EXPECT_TRUE(sweep_aabb_aabb(kUnitAabb, {0, 0.1, 0}, {{-7, 1, -1}, {-5, 3, 1}}, {16, 0.1, 0}).hit);
}

TEST(SweepAabbAabb, TouchingExactlyAtTheEndOfTheStepIsAHit) {
  const SweepHit h = sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{3, -1, -1}, {5, 1, 1}}, {-2, 0, 0});
  EXPECT_TRUE(h.hit);
  EXPECT_EQ(h.t_first, 1);
  EXPECT_EQ(h.t_last, 1);
  // One ulp farther: the faces meet at t = 1 + 2^-52, after the step (exact arithmetic here).
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{std::nextafter(3.0, 4.0), -1, -1}, {5, 1, 1}}, {-2, 0, 0}).hit);
}

TEST(SweepAabbAabb, TouchingAtTheStartOfTheStepIsAHitAtZero) {
  const SweepHit h = sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{1, -1, -1}, {3, 1, 1}}, {1, 0, 0});
  EXPECT_TRUE(h.hit);
  EXPECT_EQ(h.t_first, 0);
  EXPECT_EQ(h.t_last, 0);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(h.t_last), 0u);  // +0
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{std::nextafter(1.0, 2.0), -1, -1}, {3, 1, 1}}, {1, 0, 0}).hit);
}

TEST(SweepAabbAabb, AlreadyOverlappingStartsAtZero) {
  const SweepHit h = sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{-0.5, -0.5, -1}, {1.5, 1.5, 1}}, {16, 0, 0});
  EXPECT_TRUE(h.hit);
  EXPECT_EQ(h.t_first, 0);
  EXPECT_EQ(h.t_last, 0.09375);  // (1 - (-0.5)) / 16
  // Moving against each other: overlap until they pass, here after the step.
  const SweepHit both = sweep_aabb_aabb(kUnitAabb, {-1, 0, 0}, {{-0.5, -0.5, -1}, {1.5, 1.5, 1}}, {1, 0, 0});
  EXPECT_EQ(both.t_first, 0);
  EXPECT_EQ(both.t_last, 0.75);
}

TEST(SweepAabbAabb, ZeroRelativeVelocityIsTheStaticTest) {
  const double next = std::nextafter(1.0, 2.0);
  const std::vector<Aabb> others = {{{1, -1, -1}, {3, 1, 1}},       {{1, 1, 1}, {3, 3, 3}},      {{next, -1, -1}, {3, 1, 1}},
                                    {{0, 0, 0}, {0, 0, 0}},         {{next, next, next}, {2, 2, 2}}, {{-5, -5, -5}, {5, 5, 5}}};
  for (const Aabb& b : others) {
    for (const Vec3 velocity : {Vec3{0, 0, 0}, Vec3{0.1, -2, 1e300}}) {
      const SweepHit h = sweep_aabb_aabb(kUnitAabb, velocity, b, velocity);
      EXPECT_EQ(h.hit, test_aabb_aabb(kUnitAabb, b));
      if (h.hit) {
        EXPECT_EQ(h, (SweepHit{true, 0, 1}));
      }
    }
  }
}

TEST(SweepAabbAabb, PerAxisWindowsThatNeverMeetAreAMiss) {
  // As for the oriented boxes: x overlaps during [0.4, 1.2], y during [-0.6, 0.2].
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{-5, 0, -1}, {-3, 2, 1}}, {5, 5, 0}).hit);
  const SweepHit corner = sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{-5, -1, -1}, {-3, 1, 1}}, {5, 5, 0});
  EXPECT_TRUE(corner.hit);
  EXPECT_LE(corner.t_first, 0.4);
  EXPECT_GE(corner.t_last, 0.4);
  EXPECT_LE(corner.t_last - corner.t_first, 0x1p-49);
}

TEST(SweepAabbAabb, TimesAreExactWhenTheArithmeticIs) {
  // Quarter-unit coordinates and power-of-two relative velocities: every difference and quotient
  // is exact, and so is the answer.
  Random rng(4);
  const double speeds[] = {0, 0.5, -0.5, 1, -1, 2, -2, 4, -4, 8, -8};
  for (int n = 0; n < 2000; ++n) {
    Aabb a, b;
    Vec3 va, vb;
    for (int k = 0; k < 3; ++k) {
      a.lo[k] = rng.below(9) / 4.0 - 1, a.hi[k] = a.lo[k] + rng.below(9) / 4.0;
      b.lo[k] = rng.below(33) / 4.0 - 4, b.hi[k] = b.lo[k] + rng.below(9) / 4.0;
      va[k] = rng.below(5) - 2.0;
      vb[k] = va[k] + speeds[rng.below(11)];
    }
    const SweepHit h = sweep_aabb_aabb(a, va, b, vb);
    const ExactWindow exact = exact_sweep(a, va, b, vb);
    ASSERT_EQ(h.hit, exact.hit()) << n;
    if (!h.hit) continue;
    EXPECT_EQ(exact::rational(h.t_first), exact.first) << n;
    EXPECT_EQ(exact::rational(h.t_last), exact.last) << n;
  }
}

TEST(SweepAabbAabb, IsConservativeAndWithin2ToTheMinus49InExactArithmetic) {
  Random rng(5);
  const Rational tolerance = exact::rational(0x1p-49);
  int exact_hits = 0;
  for (int n = 0; n < 4000; ++n) {
    const AabbCase c = random_aabb_case(rng);
    const SweepHit h = sweep_aabb_aabb(c.a, c.va, c.b, c.vb);
    const ExactWindow exact = exact_sweep(c.a, c.va, c.b, c.vb);
    if (exact.hit()) {
      ++exact_hits;
      ASSERT_TRUE(h.hit) << n;
      EXPECT_LE(exact::rational(h.t_first), exact.first) << n;
      EXPECT_GE(exact::rational(h.t_first), exact.first - tolerance) << n;
      EXPECT_GE(exact::rational(h.t_last), exact.last) << n;
      EXPECT_LE(exact::rational(h.t_last), exact.last + tolerance) << n;
    } else if (h.hit) {  // a near miss: the windows miss each other by less than 2^-48
      EXPECT_LT(exact.first - exact.last, 2 * tolerance) << n;
    }
  }
  EXPECT_GT(exact_hits, 400);
}

TEST(SweepAabbAabb, GrazingContactsFoundByBisectionAreHits) {
  Random rng(10);
  int grazes = 0;
  for (int n = 0; n < 1500 && grazes < 100; ++n) {
    const AabbCase c = random_aabb_case(rng);
    if (!exact_sweep(c.a, c.va, c.b, c.vb).hit()) continue;
    const int k = rng.below(3);
    const bool on_velocity = rng.below(2) == 1;
    const auto with = [&](double x) {
      AabbCase m = c;
      if (on_velocity) {
        m.vb[k] = x;
      } else {
        m.b.hi[k] = x + (c.b.hi[k] - c.b.lo[k]);  // a translation, up to rounding
        m.b.lo[k] = x;
      }
      return m;
    };
    const auto meets_exactly = [&](double x) {
      const AabbCase m = with(x);
      return exact_sweep(m.a, m.va, m.b, m.vb).hit();
    };
    double meets = on_velocity ? c.vb[k] : c.b.lo[k];
    double misses = meets + (rng.below(2) == 1 ? 20 : -20);
    if (meets_exactly(misses)) continue;
    for (double mid = meets + (misses - meets) / 2; mid != meets && mid != misses; mid = meets + (misses - meets) / 2) {
      (meets_exactly(mid) ? meets : misses) = mid;
    }
    ++grazes;
    const AabbCase m = with(meets);
    const SweepHit h = sweep_aabb_aabb(m.a, m.va, m.b, m.vb);
    const ExactWindow exact = exact_sweep(m.a, m.va, m.b, m.vb);
    ASSERT_TRUE(h.hit) << n;
    EXPECT_LE(exact::rational(h.t_first), exact.first) << n;
    EXPECT_GE(exact::rational(h.t_first), exact.first - exact::rational(0x1p-49)) << n;
    EXPECT_GE(exact::rational(h.t_last), exact.last) << n;
    EXPECT_LE(exact::rational(h.t_last), exact.last + exact::rational(0x1p-49)) << n;
  }
  EXPECT_GE(grazes, 50);
}

TEST(SweepAabbAabb, AgreesWithSampledStaticTests) {
  Random rng(6);
  for (int n = 0; n < 4000; ++n) {
    const AabbCase c = random_aabb_case(rng);
    const SweepHit h = sweep_aabb_aabb(c.a, c.va, c.b, c.vb);
    for (int k = 0; k <= 64; ++k) {
      const double t = k / 64.0;
      if (!test_aabb_aabb(at(c.a, c.va, t), at(c.b, c.vb, t))) continue;
      ASSERT_TRUE(h.hit) << n << " t=" << t;
      EXPECT_LE(h.t_first, t) << n;
      EXPECT_GE(h.t_last, t) << n;
    }
  }
}

TEST(SweepAabbAabb, IsSymmetricBitForBit) {
  Random rng(7);
  for (int n = 0; n < 4000; ++n) {
    const AabbCase c = random_aabb_case(rng);
    EXPECT_TRUE(same_bits(sweep_aabb_aabb(c.a, c.va, c.b, c.vb), sweep_aabb_aabb(c.b, c.vb, c.a, c.va))) << n;
  }
}

TEST(SweepAabbAabb, OutOfContractInputsGiveNoHit) {
  const Aabb near{{1, -1, -1}, {3, 1, 1}};
  ASSERT_TRUE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, near, {0, 0, 0}).hit);
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{kNan, -1, -1}, {3, 1, 1}}, {0, 0, 0}).hit);
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, near, {0, kNan, 0}).hit);
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {kNan, 0, 0}, near, {0, 0, 0}).hit);
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, near, {-INFINITY, 0, 0}).hit);
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{1, -1, -1}, {INFINITY, 1, 1}}, {0, 0, 0}).hit);
  EXPECT_FALSE(sweep_aabb_aabb(kUnitAabb, {0, 0, 0}, {{3, -1, -1}, {1, 1, 1}}, {0, 0, 0}).hit);  // inverted
}

// ---- Aabb as MovingObb ----

TEST(MovingObbOfAabb, IsTheSameBoxWhenNothingRounds) {
  const MovingObb m = moving_obb({{-1, 2, 3}, {1, 3, 7}}, {1, 2, 3});
  EXPECT_EQ(m, (MovingObb{box({0, 2.5, 5}, {1, 0.5, 2}), {1, 2, 3}}));
}

TEST(MovingObbOfAabb, ContainsTheAabbAndSweepsConservatively) {
  Random rng(8);
  for (int n = 0; n < 1000; ++n) {
    const AabbCase c = random_aabb_case(rng);
    const MovingObb a = moving_obb(c.a, c.va), b = moving_obb(c.b, c.vb);
    for (const auto& [aabb, obb] : {std::pair{c.a, a.box}, std::pair{c.b, b.box}}) {
      EXPECT_EQ(obb.axes, Mat3::identity());
      for (int k = 0; k < 3; ++k) {
        EXPECT_LE(exact::rational(obb.center[k]) - exact::rational(obb.half[k]), exact::rational(aabb.lo[k])) << n;
        EXPECT_GE(exact::rational(obb.center[k]) + exact::rational(obb.half[k]), exact::rational(aabb.hi[k])) << n;
      }
    }
    const ExactWindow exact = exact_sweep(c.a, c.va, c.b, c.vb);
    const SweepHit h = sweep_obb_obb(a, b);
    if (!exact.hit()) continue;
    ASSERT_TRUE(h.hit) << n;
    EXPECT_LE(exact::rational(h.t_first), exact.first) << n;
    EXPECT_GE(exact::rational(h.t_last), exact.last) << n;
  }
}

TEST(MovingObbOfAabb, NanAndInvertedBoxesNeverHit) {
  const MovingObb a = moving(kUnit, {0, 0, 0});
  EXPECT_FALSE(sweep_obb_obb(a, moving_obb({{kNan, 0, 0}, {1, 1, 1}}, {0, 0, 0})).hit);
  EXPECT_FALSE(sweep_obb_obb(a, moving_obb({{0, 0, 0}, {1, kNan, 1}}, {0, 0, 0})).hit);
  EXPECT_FALSE(sweep_obb_obb(a, moving_obb({{0.5, 0, 0}, {0.25, 1, 1}}, {0, 0, 0})).hit);  // inverted
  EXPECT_FALSE(sweep_obb_obb(a, moving_obb({{-INFINITY, 0, 0}, {1, 1, 1}}, {0, 0, 0})).hit);
}

}  // namespace
}  // namespace cc
