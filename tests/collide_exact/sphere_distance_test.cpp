// distance_sphere_sphere and distance_sphere_obb against exact rational arithmetic
// (oracle/exact/exact_distance.h): for drawn cases biased to touching, concentric, zero radii,
// flat boxes, centres on and inside boxes, near each kind of feature and at scales 2^-300 to
// 2^300, the distance lies within its bound of the exact signed distance, each witness within
// its bound of its shape's boundary, and the witnesses as far apart as the exact distance says
// (within the bounds). The configurations are counted and each must be met.
#include "collide/sphere_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "oracle/exact/exact_distance.h"
#include "rotations.h"
#include "test_random.h"

namespace cc {
namespace {

using exact::QVec3;
using exact::Rational;
using exact::rational;

// The exact signed distance's claims. `inside_square` and `outside_square`: the exact squared
// distance of b's nearest point set to a's centre, and whether the centre is inside; the exact
// signed distance is sqrt(outside) - r, or -sqrt(depth) - r.
struct ExactSigned {
  bool inside = false;
  Rational square;  // of the centre's distance to the shape (outside) or to its boundary (inside)
};

// |s.distance - exact| <= s.distance_error, decided on squares.
testing::AssertionResult distance_within(const Separation& s, const ExactSigned& e, double radius) {
  // outside: sqrt(square) = distance + r within the error; inside: sqrt(square) = -(distance + r).
  const Rational y = rational(s.distance) + rational(radius);
  if (exact::root_within(e.square, e.inside ? Rational(-y) : y, rational(s.distance_error))) {
    return testing::AssertionSuccess();
  }
  return testing::AssertionFailure() << "distance " << s.distance << " (error " << s.distance_error
                                     << ") against the exact square " << e.square.get_d()
                                     << (e.inside ? " inside" : " outside");
}

// A witness on a ball's boundary within the point error.
testing::AssertionResult on_sphere(const Vec3& p, const Sphere& s, double error) {
  const QVec3 d = rational(p) - rational(s.center);
  if (exact::root_within(dot(d, d), rational(s.radius), rational(error))) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "a witness off its ball by more than " << error;
}

// The witnesses as far apart as the exact distance says: | |on_b - on_a| - |D| | <= 2 pe + de.
testing::AssertionResult witnesses_apart(const Separation& s) {
  const QVec3 w = rational(s.on_b) - rational(s.on_a);
  const Rational e = 2 * rational(s.point_error) + rational(s.distance_error);
  if (exact::root_within(dot(w, w), abs(rational(s.distance)), e)) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "witnesses " << std::sqrt(dot(w, w).get_d()) << " apart for a distance "
                                     << s.distance;
}

TEST(DistanceSphereSphereExact, WithinItsBounds) {
  test::Random r(41);
  std::map<std::string, int> met;
  for (int i = 0; i < 4000; ++i) {
    const double s = r.scale();
    Sphere a{s * r.in_cube(4), r.below(8) == 0 ? 0.0 : r.between(0, 3) * s};
    Sphere b{s * r.in_cube(4), r.below(8) == 0 ? 0.0 : r.between(0, 3) * s};
    switch (r.below(4)) {
      case 0:  // touching exactly: a 3-4-5 offset with radii summing to 5 (dyadic, so exact)
        b.center = a.center + s * Vec3{3, 4, 0};
        if (b.center - a.center != s * Vec3{3, 4, 0}) break;  // rounded: drawn as it is
        a.radius = r.in(0, 5) * s, b.radius = 5 * s - a.radius;
        break;
      case 1: b.center = a.center; break;  // concentric
      default: break;
    }
    const Separation sep = distance_sphere_sphere(a, b);
    const QVec3 d = rational(b.center) - rational(a.center);
    // The exact signed distance is |d| - ra - rb: |d| against distance + ra + rb, exactly.
    const ExactSigned e{false, dot(d, d)};
    const Rational y = rational(sep.distance) + rational(a.radius) + rational(b.radius);
    ASSERT_TRUE(exact::root_within(e.square, y, rational(sep.distance_error)))
        << "distance " << sep.distance << " error " << sep.distance_error << " case " << i;
    ASSERT_TRUE(on_sphere(sep.on_a, a, sep.point_error)) << i;
    ASSERT_TRUE(on_sphere(sep.on_b, b, sep.point_error)) << i;
    ASSERT_TRUE(witnesses_apart(sep)) << i;
    const Rational exact_reach = rational(a.radius) + rational(b.radius);
    const int sign = e.square == exact_reach * exact_reach ? 0 : (e.square < exact_reach * exact_reach ? -1 : 1);
    ++met[sign == 0 ? "touching" : sign < 0 ? "overlapping" : "apart"];
    if (is_zero(d)) ++met["concentric"];
    if (a.radius == 0 || b.radius == 0) ++met["a point"];
    if (s <= 0x1p-200) ++met["tiny"];
    if (s >= 0x1p200) ++met["huge"];
  }
  for (const char* c : {"touching", "overlapping", "apart", "concentric", "a point", "tiny", "huge"}) {
    EXPECT_GT(met[c], 20) << c;
  }
}

// The box in a configuration drawn relative to it: its centre, extents and axes at scale s.
Obb draw_box(test::Random& r, double s, bool& skewed) {
  Vec3 half{r.between(0, 3) * s, r.between(0, 3) * s, r.between(0, 3) * s};
  if (r.below(6) == 0) half[r.below(3)] = 0;  // flat
  if (r.below(8) == 0) half = {};             // a point
  Mat3 axes = r.below(3) == 0 ? Mat3::identity()
                              : test::rotation(r.between(-3, 3), r.between(-3, 3), r.between(-3, 3));
  skewed = r.below(3) == 0;
  if (skewed) {  // skewed within the tolerance: a longer axis, one leaning on another
    axes.col[0] = (1 + 0x1p-50) * axes.col[0];
    axes.col[1] = axes.col[1] + 0x1p-50 * axes.col[2];
  }
  return {s * r.in_cube(4), half, axes};
}

// A point in the box's frame: on a face, an edge or a corner (each coordinate at +-half or
// inside), pushed out along some of the held coordinates, or inside.
Vec3 draw_local_point(test::Random& r, const Obb& box, double s) {
  Vec3 q;
  for (int i = 0; i < 3; ++i) {
    const double h = box.half[i];
    switch (r.below(4)) {
      case 0: q[i] = h; break;
      case 1: q[i] = -h; break;
      case 2: q[i] = r.below(2) ? h + r.between(0, 2) * s : -h - r.between(0, 2) * s; break;
      default: q[i] = r.between(-h, h); break;
    }
  }
  return q;
}

TEST(DistanceSphereObbExact, WithinItsBounds) {
  test::Random r(43);
  std::map<std::string, int> met;
  for (int i = 0; i < 4000; ++i) {
    const double s = r.scale();
    bool skewed = false;
    Obb box = draw_box(r, s, skewed);
    Vec3 local = draw_local_point(r, box, s);
    Sphere ball{box.center + box.axes * local, r.below(8) == 0 ? 0.0 : r.between(0, 2) * s};
    if (r.below(5) == 0) {  // touching a face exactly: small integers times a power of two
      const double unit = std::ldexp(1.0, r.in(-300, 300));
      skewed = false;
      box = {unit * Vec3{double(r.in(-9, 9)), double(r.in(-9, 9)), double(r.in(-9, 9))},
             unit * Vec3{double(r.in(0, 4)), double(r.in(0, 4)), double(r.in(0, 4))}, Mat3::identity()};
      const int k = r.below(3);
      ball.radius = r.in(0, 3) * unit;
      for (int j = 0; j < 3; ++j) local[j] = r.in(-int(box.half[j] / unit), int(box.half[j] / unit)) * unit;
      local[k] = (r.below(2) ? 1 : -1) * (box.half[k] + ball.radius);
      ball.center = box.center + local;
    }
    const Separation sep = distance_sphere_obb(ball, box);
    const QVec3 c = rational(ball.center);
    const bool inside = exact::in_box(c, box);
    const ExactSigned e{inside, inside ? exact::squared_depth_in_box(c, box) : exact::squared_distance_to_box(c, box)};
    ASSERT_TRUE(distance_within(sep, e, ball.radius)) << "case " << i;
    ASSERT_TRUE(on_sphere(sep.on_a, ball, sep.point_error)) << i;
    // The box's witness: on the box's boundary within the point error.
    const QVec3 w = rational(sep.on_b);
    const Rational off = exact::in_box(w, box) ? exact::squared_depth_in_box(w, box) : exact::squared_distance_to_box(w, box);
    ASSERT_LE(off, rational(sep.point_error) * rational(sep.point_error)) << i;
    ASSERT_TRUE(witnesses_apart(sep)) << i;
    int held = 0;
    for (int k = 0; k < 3; ++k) held += std::fabs(local[k]) >= box.half[k];
    ++met[inside ? (e.square == 0 ? "centre on the boundary" : "centre inside") : "centre outside"];
    if (!inside) ++met["outside, " + std::to_string(held) + " coordinates held"];
    const Rational reach = rational(ball.radius);
    if (!inside && e.square == reach * reach) ++met["touching"];
    if (box.half.x == 0 || box.half.y == 0 || box.half.z == 0) ++met["flat box"];
    if (box.half == Vec3{}) ++met["a point box"];
    if (skewed && box.axes.col[0] != Vec3{1, 0, 0}) ++met["skewed axes"];
    if (s <= 0x1p-200) ++met["tiny"];
    if (s >= 0x1p200) ++met["huge"];
  }
  for (const char* c : {"touching", "centre on the boundary", "centre inside", "centre outside", "outside, 1 coordinates held",
                        "outside, 2 coordinates held", "outside, 3 coordinates held", "flat box", "a point box", "skewed axes", "tiny", "huge"}) {
    EXPECT_GT(met[c], 20) << c;
  }
  for (const auto& [c, n] : met) std::cout << c << ": " << n << "\n";
}

}  // namespace
}  // namespace cc
