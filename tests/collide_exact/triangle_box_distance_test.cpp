// distance_triangle_obb against exact rational arithmetic (oracle/exact/exact_polytope_distance.h,
// the hull of the shapes' Minkowski difference): for drawn triangles against a box, biased to a
// vertex, an edge or the whole triangle against a face at a gap of 0, a few ulps or small
// fractions either way, to edges crossing the box's edges, to deep overlaps, degenerate triangles
// (segments, points, needles), edges parallel and nearly parallel to the box's axes, flat and
// long boxes, axes skewed within the tolerance, and scales 2^-300 to 2^300: the signed distance
// lies within its bound of the exact one, each witness within its bound of its shape, and the
// witnesses as far apart as the distance says (distance_check.h). Each configuration must be met.
#include "collide/triangle_box_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "oracle/exact/distance_check.h"
#include "oracle/exact/exact_polytope_distance.h"
#include "rotations.h"
#include "test_random.h"

namespace cc {
namespace {

Mat3 draw_rotation(test::Random& r) { return test::rotation(r.between(-3, 3), r.between(-3, 3), r.between(-3, 3)); }

Vec3 draw_half(test::Random& r, double s, std::string& how) {
  Vec3 half{r.between(0.05, 3) * s, r.between(0.05, 3) * s, r.between(0.05, 3) * s};
  if (r.below(5) == 0) half[r.below(3)] *= std::ldexp(1.0, -r.in(10, 40)), how += " long box";
  if (r.below(8) == 0) half[r.below(3)] = 0, how += " flat box";
  return half;
}

// A gap: 0, a few ulps either way, a small fraction of the size either way, or up to the size.
double draw_gap(test::Random& r, double size, std::string& how) {
  switch (r.below(5)) {
    case 0: how += " touching"; return 0;
    case 1: how += " ulps"; return (r.below(2) ? 1 : -1) * r.in(1, 8) * 0x1p-52 * size;
    case 2: how += " fraction"; return (r.below(2) ? 1 : -1) * std::ldexp(size, -r.in(10, 40));
    default: return r.between(-1, 1) * size;
  }
}

// A unit direction in the plane perpendicular to n, along one of the box's axes (parallel
// edges), turned from it by a few ulps or a small angle (nearly parallel), or any.
Vec3 draw_lateral(test::Random& r, const Obb& box, int k, std::string& how) {
  const Vec3 along = box.axes.col[(k + 1 + r.below(2)) % 3];
  const Vec3 other = cross(box.axes.col[k], along);
  switch (r.below(4)) {
    case 0: how += " parallel edge"; return along;
    case 1: {
      how += " nearly parallel edge";
      const double angle = r.below(2) ? std::ldexp(1.0, -r.in(20, 50)) : r.between(1e-9, 1e-3);
      return along + angle * other;
    }
    default: {
      const double a = r.between(0, 6.3);
      return std::cos(a) * along + std::sin(a) * other;
    }
  }
}

// A triangle against face k of the box (outward normal n): a vertex, an edge or the whole
// triangle at the face's height plus a drawn gap, laterally anywhere near the face, the rest
// rising away from it (or sinking through it).
Triangle against_a_face(test::Random& r, const Obb& box, double size, std::string& how) {
  const int k = r.below(3);
  const Vec3 n = (r.below(2) ? 1.0 : -1.0) * box.axes.col[k];
  Vec3 lateral;
  for (int j = 0; j < 3; ++j) lateral[j] = j == k ? 0 : r.between(-1.3, 1.3) * box.half[j];
  const double gap = draw_gap(r, size, how);
  const Vec3 p = box.center + box.axes * lateral + (box.half[k] + gap) * n;
  const Vec3 e = draw_lateral(r, box, k, how);
  const double len = r.between(0.1, 3) * size;
  const double rise = r.below(4) == 0 ? -r.between(0, 2) * size : r.between(0, 3) * size;
  Triangle t;
  switch (r.below(3)) {
    case 0: {  // a vertex
      how += " vertex";
      const Vec3 f = cross(n, e);
      t = {{p, p + len * e + rise * n, p + len * f + (rise + r.between(0, 1) * size) * n}};
      break;
    }
    case 1: {  // an edge
      how += " edge";
      const Vec3 f = cross(n, e);
      t = {{p, p + len * e, p + r.between(-1, 1) * len * f + rise * n}};
      break;
    }
    default: {  // the whole triangle, parallel to the face
      how += " parallel face";
      const Vec3 f = cross(n, e);
      t = {{p, p + len * e, p + r.between(-1, 1) * len * e + len * f}};
      break;
    }
  }
  return t;
}

// A triangle through or near the box: its vertices anywhere within twice the size (deep and
// crossing), or degenerate: a segment, a point, a needle.
Triangle near(test::Random& r, const Obb& box, double size, std::string& how) {
  const auto any = [&](double reach) { return box.center + (reach * size) * r.in_cube(1); };
  Triangle t{{any(2), any(2), any(2)}};
  switch (r.below(5)) {
    case 0: how += " segment"; t.v[2] = t.v[0] + r.between(-1, 2) * (t.v[1] - t.v[0]); break;
    case 1: how += " point"; t.v[1] = t.v[2] = t.v[0]; break;
    case 2: how += " needle"; t.v[2] = t.v[0] + r.between(0, 1) * (t.v[1] - t.v[0]) + std::ldexp(size, -r.in(20, 50)) * r.in_cube(1); break;
    default: break;
  }
  return t;
}

// An axis-aligned box and a triangle on the dyadic grid touching a face, an edge or a corner
// exactly.
void touching_on_a_grid(test::Random& r, double s, Triangle& t, Obb& box) {
  box = {s * r.integer_point(4), {s * r.in(0, 3), s * r.in(0, 3), s * r.in(1, 3)}, Mat3::identity()};
  Vec3 p = box.center;
  for (int k = 0; k < 3; ++k) {
    const int side = r.below(3) - 1;  // -1, 0 or +1: on a face, an edge or a corner
    p[k] += side * box.half[k];
  }
  const int k = r.below(3);
  p[k] = box.center[k] + box.half[k];  // at least on the top face of axis k
  Vec3 up;
  up[k] = s;
  t = {{p, p + up + s * r.integer_point(2), p + 2 * up + s * r.integer_point(2)}};
  // The others at or above the face.
  for (int i = 1; i < 3; ++i) t.v[i][k] = std::max(t.v[i][k], p[k]);
}

// The library's answer for t against the box, the exact signed distance, and what is wrong with
// the answer judged against it (distance_check.h): nothing when it holds.
struct Judged {
  Separation answer;
  exact::ExactSignedDistance exact;
  std::optional<std::string> wrong;
};
Judged judged(const Triangle& t, const Obb& box) {
  Judged j{distance_triangle_obb(t, box), {}, {}};
  const auto ct = exact::triangle_corners(t);
  const auto cb = exact::box_corners(box);
  j.exact = exact::exact_polytope_distance(ct, cb);
  const Separation& s = j.answer;
  const harness::DistanceClaim claim{s.distance, true, s.on_a, s.on_b, s.distance_error, s.point_error};
  j.wrong = exact::distance_check(j.exact, exact::boundary_of(t), exact::boundary_of(box))(claim);
  return j;
}

TEST(DistanceTriangleObbExact, WithinItsBounds) {
  test::Random r(2026);
  std::map<std::string, int> met;
  for (int i = 0; i < 1500; ++i) {
    const double s = r.scale();
    std::string how;
    Triangle t;
    Obb box;
    if (r.below(6) == 0) {
      touching_on_a_grid(r, s, t, box);
      how = " grid";
    } else {
      box = {s * r.in_cube(4), draw_half(r, s, how), r.below(4) == 0 ? Mat3::identity() : draw_rotation(r)};
      if (r.below(4) == 0) {  // skewed within the tolerance
        box.axes.col[0] = (1 + 0x1p-50) * box.axes.col[0];
        box.axes.col[1] = box.axes.col[1] + 0x1p-50 * box.axes.col[2];
      }
      const double size = std::max({box.half.x, box.half.y, box.half.z, s});
      t = r.below(3) == 0 ? near(r, box, size, how) : against_a_face(r, box, size, how);
    }
    const auto [sep, e, wrong] = judged(t, box);
    ASSERT_FALSE(wrong) << *wrong << " (case " << i << ":" << how << ", distance " << sep.distance << ", error "
                        << sep.distance_error << ", points " << sep.point_error << ")";
    const double exact = exact::rounded_down(e);
    const double size = std::max({box.half.x, box.half.y, box.half.z, s});
    ++met[sgn(e.squared) == 0 ? "touching" : e.sign < 0 ? "overlapping" : "apart"];
    if (sgn(e.squared) != 0 && std::fabs(exact) < 0x1p-30 * size) ++met[e.sign < 0 ? "just overlapping" : "just apart"];
    for (const char* c : {"vertex", "edge", "parallel face", "parallel edge", "nearly parallel edge", "segment", "point",
                          "needle", "flat box", "long box", "grid"}) {
      if (how.find(c) != std::string::npos) ++met[c];
    }
    if (s <= 0x1p-200) ++met["tiny"];
    if (s >= 0x1p200) ++met["huge"];
    // Tight where nothing is parallel or thin: within 2^-36 of the size. Where an edge is parallel
    // to a box axis (to the rounding of its vertices, or nearly), closest pairs are not unique and
    // the witnesses' direction errs by their rounding over their distance, which the box's extent
    // across it multiplies: within 2^-20 of the size.
    if (std::isfinite(sep.distance)) {
      const bool parallel = how.find("parallel edge") != std::string::npos || how.find("needle") != std::string::npos;
      EXPECT_LE(sep.distance_error, (parallel ? 0x1p-20 : 0x1p-36) * (size + std::fabs(exact))) << i << how;
    }
  }
  for (const char* c : {"touching", "overlapping", "apart", "just overlapping", "just apart", "vertex", "edge",
                        "parallel face", "parallel edge", "nearly parallel edge", "segment", "point", "needle",
                        "flat box", "long box", "grid", "tiny", "huge"}) {
    EXPECT_GT(met[c], 10) << c;
  }
}

// A needle triangle (its three vertices within 2^-k of a line) lying along a box's edge direction
// and pressed into a face: every edge is nearly parallel to that axis, so their slivers neighbour
// each other, and the sum of their widths, not the largest, bounds what leaving them out costs.
TEST(DistanceTriangleObbExact, ANeedleAlongABoxEdge) {
  const Mat3 place = test::rotation(0.3, -0.8, 1.9);
  const Obb box{{0, 0, 0}, {2, 1, 0.5}, place};
  int checked = 0;
  for (const int k : {20, 30, 45, 52}) {
    for (const double depth : {0x1p-40, 0x1p-20, 0.125}) {
      const double w = std::ldexp(1.0, -k);
      const Vec3 base = place * Vec3{-3, 0.25, 0.5 - depth};
      const Triangle t{{base, base + place * Vec3{6, w, w}, base + place * Vec3{3, -w, 2 * w}}};
      const auto [sep, e, wrong] = judged(t, box);
      ASSERT_FALSE(wrong) << *wrong << " (2^-" << k << ", depth " << depth << ")";
      checked += e.sign < 0;
    }
  }
  EXPECT_GT(checked, 8);
}

// A triangle's edge nearly parallel to a box's vertical edge (turned by theta about the diagonal
// (1, 1, 0)), pressed into it along the diagonal by delta on x and on y, the triangle rising away
// along the diagonal: the face of the difference from those edges is a bevel sqrt 2 delta deep
// where the box's faces are delta + theta / sqrt 2, so for delta below 1.7 theta the depth is the
// bevel's. Everything is placed by one rotation, so the edge's difference and its cross product
// with the box's axis round: the axis is measured (not left out as a sliver) and the bound stays
// at the rounding's scale.
TEST(DistanceTriangleObbExact, AnEdgeNearlyParallelToABoxEdgeMeetingItAtTheBevel) {
  const Mat3 place = test::rotation(0.4, -1.3, 2.2);
  const Obb box{{0, 0, 0}, {1, 1, 1}, place};
  const double h = std::sqrt(0.5);
  int bevel_deepest = 0;
  for (const int theta_exponent : {-20, -26, -30}) {
    const double theta = std::ldexp(1.0, theta_exponent);
    for (const double delta_in_thetas : {0.25, 0.5, 1.0, 4.0}) {
      const double delta = delta_in_thetas * theta;
      const Vec3 through{1 - delta, 1 - delta, 0}, along{-h * theta, h * theta, 1};
      const Triangle t{{place * (through + along), place * (through - along), place * Vec3{3, 3, 0}}};
      const auto [sep, e, wrong] = judged(t, box);
      ASSERT_LT(e.sign, 0);
      ASSERT_FALSE(wrong) << *wrong << " (theta 2^" << theta_exponent << ", delta " << delta_in_thetas << " theta)";
      const exact::Rational face = exact::rational(delta + theta * h);
      if (e.squared < face * face * exact::Rational(99, 100)) ++bevel_deepest;
      EXPECT_LE(sep.distance_error, 0x1p-40) << "theta 2^" << theta_exponent << ", delta " << delta_in_thetas;
    }
  }
  EXPECT_GT(bevel_deepest, 5);
}

// A box 1000 long whose second axis leans on its first by the whole orthonormality tolerance
// (2^-48): its face across the first axis is turned by 2^-48 from that axis, and a triangle's
// vertex pressed into that face at its far end is less deep along the face's normal than along
// the axis, by some 2000 times the lean. The face axes' term of the bound covers it.
TEST(DistanceTriangleObbExact, AxesLeaningByTheToleranceCountTheirLean) {
  const Mat3 leaning = Mat3::from_columns({1, 0, 0}, {0x1p-48, 1, 0}, {0, 0, 1});
  const Obb box{{0, 0, 0}, {1, 1000, 1}, leaning};
  int checked = 0;
  for (const double delta : {0x1p-30, 0.01, 0.25}) {
    const Triangle t{{Vec3{1 - delta, -999.5, 0}, Vec3{3, -999, 0.5}, Vec3{2.5, -999.75, -0.5}}};
    const auto [sep, e, wrong] = judged(t, box);
    ASSERT_FALSE(wrong) << *wrong << " (delta " << delta << ")";
    checked += e.sign < 0;
  }
  EXPECT_EQ(checked, 3);
}

}  // namespace
}  // namespace cc
