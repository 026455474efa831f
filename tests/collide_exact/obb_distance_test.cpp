// distance_obb_obb against exact rational arithmetic (oracle/exact/exact_polytope_distance.h, the
// hull of the boxes' Minkowski difference): for drawn pairs biased to touching exactly, a few ulps
// and small fractions apart or deep, parallel and nearly parallel edges (the same rotation, or
// one turned by a few ulps), flat boxes, segments and points, axes skewed within the tolerance, and
// scales 2^-300 to 2^300, the signed distance lies within its bound of the exact one, each witness
// within its bound of its box's boundary, and the witnesses as far apart as the distance says
// (distance_check.h). The configurations are counted and each must be met.
#include "collide/obb_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "oracle/exact/distance_check.h"
#include "oracle/exact/exact_polytope_distance.h"
#include "rotations.h"
#include "test_random.h"

namespace cc {
namespace {

using exact::Rational;

Vec3 draw_half(test::Random& r, double s) {
  Vec3 half{r.between(0.05, 3) * s, r.between(0.05, 3) * s, r.between(0.05, 3) * s};
  if (r.below(4) == 0) half[r.below(3)] *= std::ldexp(1.0, -r.in(10, 40));  // long and thin, or flat-ish
  if (r.below(8) == 0) half[r.below(3)] = 0;                                  // flat
  if (r.below(16) == 0) half[r.below(3)] = 0, half[r.below(3)] = 0;           // a segment (or flat)
  return half;
}

Mat3 draw_rotation(test::Random& r) { return test::rotation(r.between(-3, 3), r.between(-3, 3), r.between(-3, 3)); }

// b's axes: a's (every edge parallel to three of b's), a's turned by a few ulps or by a small angle
// (nearly parallel), the identity, or any.
Mat3 draw_b_axes(test::Random& r, const Mat3& a, std::string& how) {
  switch (r.below(5)) {
    case 0: how = "parallel edges"; return a;
    case 1: {
      how = "nearly parallel edges";
      const double angle = r.below(2) ? std::ldexp(1.0, -r.in(20, 50)) : r.between(1e-9, 1e-3);
      const Mat3 turn = test::rotation(angle, r.below(2) ? angle : 0, 0);
      Mat3 m;
      for (int k = 0; k < 3; ++k) m.col[k] = a * (turn * Mat3::identity().col[k]);
      return m;
    }
    case 2: how = ""; return Mat3::identity();
    default: how = ""; return draw_rotation(r);
  }
}

// The radius of b's projection on a unit direction.
double radius_along(const Obb& b, const Vec3& n) {
  double r = 0;
  for (int k = 0; k < 3; ++k) r += b.half[k] * std::fabs(dot(b.axes.col[k], n));
  return r;
}

// A gap drawn for a placement: 0, a few ulps either way, a small fraction of the size either way,
// or anything up to the size either way.
double draw_gap(test::Random& r, double size) {
  switch (r.below(5)) {
    case 0: return 0;
    case 1: return (r.below(2) ? 1 : -1) * r.in(1, 8) * 0x1p-52 * size;
    case 2: return (r.below(2) ? 1 : -1) * std::ldexp(size, -r.in(10, 40));
    default: return r.between(-1, 1) * size;
  }
}

struct Pair {
  Obb a, b;
};

// Two axis-aligned boxes with dyadic extents touching exactly at a face, an edge or a corner.
Pair touching_on_a_grid(test::Random& r, double s) {
  Pair p;
  p.a = {s * r.integer_point(4), {s * r.in(0, 3), s * r.in(0, 3), s * r.in(1, 3)}, Mat3::identity()};
  p.b.half = {s * r.in(0, 3), s * r.in(0, 3), s * r.in(1, 3)};
  p.b.axes = Mat3::identity();
  Vec3 offset;
  for (int k = 0; k < 3; ++k) {
    const double reach = p.a.half[k] + p.b.half[k];
    offset[k] = k == 0 || r.below(3) == 0 ? (r.below(2) ? reach : -reach) : s * r.in(-1, 1) * 0.5 * (reach > 0 ? 1 : 0);
  }
  p.b.center = p.a.center + offset;
  return p;
}

// b placed against one of a's faces (or of its edges' directions) at a drawn gap, laterally
// anywhere near it; or anywhere near a, or deep in it.
Pair near(test::Random& r, double s, std::string& how) {
  Pair p;
  p.a = {s * r.in_cube(4), draw_half(r, s), r.below(4) == 0 ? Mat3::identity() : draw_rotation(r)};
  if (r.below(4) == 0) {  // skewed within the tolerance
    p.a.axes.col[0] = (1 + 0x1p-50) * p.a.axes.col[0];
    p.a.axes.col[1] = p.a.axes.col[1] + 0x1p-50 * p.a.axes.col[2];
  }
  p.b = {{}, draw_half(r, s), draw_b_axes(r, p.a.axes, how)};
  const double size = std::max({p.a.half.x, p.a.half.y, p.a.half.z, p.b.half.x, p.b.half.y, p.b.half.z, s});
  switch (r.below(4)) {
    case 0: case 1: {
      // Against a face of a: along its normal at a's half + b's radius + the gap.
      const int k = r.below(3);
      const Vec3 n = (r.below(2) ? 1.0 : -1.0) * p.a.axes.col[k];
      Vec3 lateral;
      for (int j = 0; j < 3; ++j) lateral[j] = j == k ? 0 : r.between(-1.2, 1.2) * p.a.half[j];
      p.b.center = p.a.center + p.a.axes * lateral + (p.a.half[k] + radius_along(p.b, n) + draw_gap(r, size)) * n;
      break;
    }
    case 2: p.b.center = p.a.center + (r.between(0, 0.3) * size) * r.in_cube(1); break;  // deep
    default: p.b.center = p.a.center + (2 * size) * r.in_cube(1); break;
  }
  return p;
}

TEST(DistanceObbObbExact, WithinItsBounds) {
  test::Random r(2026);
  std::map<std::string, int> met;
  for (int i = 0; i < 1500; ++i) {
    const double s = r.scale();
    std::string how;
    const Pair p = r.below(5) == 0 ? touching_on_a_grid(r, s) : near(r, s, how);
    const Separation sep = distance_obb_obb(p.a, p.b);
    const auto ca = exact::box_corners(p.a), cb = exact::box_corners(p.b);
    const exact::ExactSignedDistance e = exact::exact_polytope_distance(ca, cb);
    const auto check = exact::distance_check(e, exact::boundary_of(p.a), exact::boundary_of(p.b));
    const harness::DistanceClaim claim{sep.distance, true, sep.on_a, sep.on_b, sep.distance_error, sep.point_error};
    const auto wrong = check(claim);
    ASSERT_FALSE(wrong) << *wrong << " (case " << i << ", " << how << ", error " << sep.distance_error << ", points "
                        << sep.point_error << ")";
    const double exact = exact::rounded_down(e);
    const double size = std::max({p.a.half.x, p.a.half.y, p.a.half.z, p.b.half.x, p.b.half.y, p.b.half.z});
    ++met[sgn(e.squared) == 0 ? "touching" : e.sign < 0 ? "overlapping" : "apart"];
    if (sgn(e.squared) != 0 && std::fabs(exact) < 0x1p-30 * size) ++met[e.sign < 0 ? "just overlapping" : "just apart"];
    if (!how.empty()) ++met[how];
    for (const Obb* b : {&p.a, &p.b}) {
      if (b->half.x == 0 || b->half.y == 0 || b->half.z == 0) ++met["flat"];
    }
    if (s <= 0x1p-200) ++met["tiny"];
    if (s >= 0x1p200) ++met["huge"];
    // Tight where nothing is nearly parallel: within 2^-36 of the size.
    if (how.empty() && std::isfinite(sep.distance)) {
      EXPECT_LE(sep.distance_error, 0x1p-36 * (size + std::fabs(exact))) << i;
    }
  }
  for (const char* c : {"touching", "overlapping", "apart", "just overlapping", "just apart", "parallel edges",
                        "nearly parallel edges", "flat", "tiny", "huge"}) {
    EXPECT_GT(met[c], 10) << c;
  }
}

// Two boxes whose vertical edges are nearly parallel (b turned by theta about the diagonal
// (1, 1, 0)), pressed edge into edge along the diagonal by delta on x and on y. The face of a - b
// from those edges is a bevel across the corner of the difference's square section, sqrt 2 delta
// deep where the faces are delta + theta / sqrt 2: for delta below 1.7 theta the depth is the
// bevel's. The edge pair's axis is measured for every theta here (its cross product's direction is
// known to 4u), so the answer is sound and its bound tight.
TEST(DistanceObbObbExact, NearlyParallelEdgesMeetingAtACorner) {
  int bevel_deepest = 0;
  for (const int theta_exponent : {-20, -23, -26, -30, -40}) {
    const double theta = std::ldexp(1.0, theta_exponent);
    const double c = std::cos(theta), s = std::sin(theta), h = std::sqrt(0.5);
    // The rotation by theta about (h, h, 0) (Rodrigues), rounded: orthonormal within the tolerance.
    const Mat3 turn = Mat3::from_columns({c + h * h * (1 - c), h * h * (1 - c), -h * s},
                                         {h * h * (1 - c), c + h * h * (1 - c), h * s}, {h * s, -h * s, c});
    for (const double delta_in_thetas : {0.125, 0.5, 1.0, 2.0, 8.0}) {
      const double delta = delta_in_thetas * theta;
      // Both placed by one rotation, so that the edges' cross product rounds.
      const Mat3 place = test::rotation(0.4, -1.3, 2.2);
      Mat3 b_axes;
      for (int k = 0; k < 3; ++k) b_axes.col[k] = place * turn.col[k];
      const Obb a{{0, 0, 0}, {1, 1, 1}, place};
      const Obb b{place * Vec3{2 - delta, 2 - delta, 0}, {1, 1, 1}, b_axes};
      const Separation sep = distance_obb_obb(a, b);
      const auto ca = exact::box_corners(a), cb = exact::box_corners(b);
      const exact::ExactSignedDistance e = exact::exact_polytope_distance(ca, cb);
      ASSERT_LT(e.sign, 0);
      const harness::DistanceClaim claim{sep.distance, true, sep.on_a, sep.on_b, sep.distance_error, sep.point_error};
      const auto wrong = exact::distance_check(e, exact::boundary_of(a), exact::boundary_of(b))(claim);
      ASSERT_FALSE(wrong) << *wrong << " (theta 2^" << theta_exponent << ", delta " << delta_in_thetas
                          << " theta, error " << sep.distance_error << ")";
      // The faces' least overlap is delta + theta / sqrt 2, the bevel's sqrt 2 delta.
      const Rational face = exact::rational(delta + theta * h);
      if (e.squared < face * face * Rational(99, 100)) ++bevel_deepest;
      // Measured on the edges' own axis, whose direction the accurate cross product knows to 4u:
      // the bound stays at the rounding's scale.
      EXPECT_LE(sep.distance_error, 0x1p-40) << "theta 2^" << theta_exponent << ", delta " << delta_in_thetas;
    }
  }
  EXPECT_GT(bevel_deepest, 5);  // the bevel, not a face, is the depth in many of them
}

// A long box whose second axis leans on its first by the whole orthonormality tolerance (2^-48):
// its face across the first axis is then turned by 2^-48 from that axis, and a small turned box
// pressed into that face at its far end is less deep along the face's normal than along the
// axis, by some 2000 times the lean. The face axes' term of the bound covers it.
TEST(DistanceObbObbExact, AxesLeaningByTheToleranceCountTheirLean) {
  const Mat3 leaning = Mat3::from_columns({1, 0, 0}, {0x1p-48, 1, 0}, {0, 0, 1});
  const Obb a{{0, 0, 0}, {1, 1000, 1}, leaning};
  int checked = 0;
  for (const double delta : {0.01, 0.1, 0.25}) {
    for (const double turn : {0.3, 0.7, 1.1}) {
      const Obb b{{1.25 - delta, -999.25, 0}, {0.5, 0.25, 0.25}, test::rotation(turn, 2 * turn, -turn)};
      const Separation sep = distance_obb_obb(a, b);
      const auto ca = exact::box_corners(a), cb = exact::box_corners(b);
      const exact::ExactSignedDistance e = exact::exact_polytope_distance(ca, cb);
      const harness::DistanceClaim claim{sep.distance, true, sep.on_a, sep.on_b, sep.distance_error, sep.point_error};
      const auto wrong = exact::distance_check(e, exact::boundary_of(a), exact::boundary_of(b))(claim);
      ASSERT_FALSE(wrong) << *wrong << " (delta " << delta << ", turn " << turn << ")";
      checked += e.sign < 0;
    }
  }
  EXPECT_EQ(checked, 9);
}

}  // namespace
}  // namespace cc
