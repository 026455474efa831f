// distance_sphere_sphere and distance_sphere_obb on configurations whose answers are known
// exactly: apart, touching, overlapping, concentric, inside a box near each kind of feature, and
// outside the domain. tests/collide_exact/sphere_distance_test.cpp checks the bounds in rationals.
#include "collide/sphere_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "rotations.h"

namespace cc {
namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();

void expect_vec(const Vec3& got, const Vec3& want, double within) {
  EXPECT_NEAR(got.x, want.x, within);
  EXPECT_NEAR(got.y, want.y, within);
  EXPECT_NEAR(got.z, want.z, within);
}

TEST(DistanceSphereSphere, ApartTouchingOverlappingAlongTheCentres) {
  // Centres 5 apart (3-4-0): apart by 1, touching, overlapping by 2.
  for (const auto& [ra, rb, want] : {std::tuple{1.0, 3.0, 1.0}, {2.0, 3.0, 0.0}, {3.0, 4.0, -2.0}}) {
    const Separation s = distance_sphere_sphere({{0, 0, 0}, ra}, {{3, 4, 0}, rb});
    EXPECT_NEAR(s.distance, want, s.distance_error);
    EXPECT_LE(s.distance_error, 0x1p-40);  // 8u of (5 + the radii)
    expect_vec(s.on_a, {0.6 * ra, 0.8 * ra, 0}, 1e-14);
    expect_vec(s.on_b, {3 - 0.6 * rb, 4 - 0.8 * rb, 0}, 1e-14);
  }
}

TEST(DistanceSphereSphere, ConcentricBallsOverlapByTheSumOfTheRadii) {
  const Separation s = distance_sphere_sphere({{1, 2, 3}, 2}, {{1, 2, 3}, 0.5});
  EXPECT_EQ(s.distance, -2.5);
  EXPECT_EQ(s.on_a.x - s.on_b.x, 2.5);  // along x, as documented
}

TEST(DistanceSphereSphere, SwappingNegatesTheDirection) {
  const Sphere a{{0.1, -7, 3e3}, 0.25}, b{{-2, 1e-3, 2.9e3}, 7};
  const Separation ab = distance_sphere_sphere(a, b), ba = distance_sphere_sphere(b, a);
  EXPECT_EQ(ab.distance, ba.distance);
  EXPECT_EQ(ab.on_a, ba.on_b);
  EXPECT_EQ(ab.on_b, ba.on_a);
}

// The scaling keeps the relative accuracy at both ends of the domain.
TEST(DistanceSphereSphere, TinyAndHugeScales) {
  for (const double s : {0x1p-600, 0x1p-300, 0x1p300, 0x1p500}) {
    const Separation r = distance_sphere_sphere({{0, 0, 0}, 1 * s}, {{3 * s, 4 * s, 0}, 3 * s});
    EXPECT_NEAR(r.distance / s, 1.0, 1e-14) << s;
    EXPECT_LE(r.distance_error / s, 1e-14) << s;
  }
}

TEST(DistanceSphereSphere, OutsideTheDomainIsNaN) {
  // Each value of either ball: NaN, infinite, a negative radius.
  const double kInf = HUGE_VAL;
  for (const Sphere& bad : {Sphere{{kNan, 0, 0}, 1}, Sphere{{0, -kInf, 0}, 1}, Sphere{{0, 0, kNan}, 1},
                            Sphere{{0, 0, 0}, -1}, Sphere{{0, 0, 0}, -0x1p-1074}, Sphere{{0, 0, 0}, kInf},
                            Sphere{{0, 0, 0}, kNan}}) {
    for (const bool first : {true, false}) {
      const Sphere good{{0, 0, 0}, 1};
      const Separation s = first ? distance_sphere_sphere(bad, good) : distance_sphere_sphere(good, bad);
      EXPECT_TRUE(std::isnan(s.distance)) << bad.radius << (first ? " first" : " second");
      EXPECT_TRUE(std::isinf(s.distance_error));
    }
  }
}

const Obb kBox{{0, 0, 0}, {1, 2, 3}, Mat3::identity()};

TEST(DistanceSphereObb, OutsideAFaceAnEdgeAndACorner) {
  struct Case {
    Vec3 center;
    double distance;
    Vec3 on_box;
  };
  for (const Case& c : {Case{{3, 0.5, -1}, 2 - 0.5, {1, 0.5, -1}},     // before the +x face
                        Case{{4, 6, 0}, 5 - 0.5, {1, 2, 0}},           // beside the x-y edge (3-4-5)
                        Case{{-4, -6, 15}, 13 - 0.5, {-1, -2, 3}}}) {  // beyond a corner (3-4-12)
    const Separation s = distance_sphere_obb({c.center, 0.5}, kBox);
    EXPECT_NEAR(s.distance, c.distance, s.distance_error) << c.center.x;
    EXPECT_EQ(s.on_b, c.on_box);
    EXPECT_LE(s.distance_error, 0x1p-36);  // 8 eta of |d|_1 + |half|_1, at most 26
  }
}

TEST(DistanceSphereObb, InsideThroughTheNearestFace) {
  // 0.25 from the +y face, 0.75 from the -x face: out through +y.
  const Separation s = distance_sphere_obb({{-0.25, 1.75, 0}, 0.5}, kBox);
  EXPECT_EQ(s.distance, -0.75);
  EXPECT_EQ(s.on_b, (Vec3{-0.25, 2, 0}));
  EXPECT_EQ(s.on_a, (Vec3{-0.25, 1.25, 0}));
  // The centre at the box's centre: the nearest face is x's (room 1), the + side.
  const Separation c = distance_sphere_obb({{0, 0, 0}, 0}, kBox);
  EXPECT_EQ(c.distance, -1);
  EXPECT_EQ(c.on_b, (Vec3{1, 0, 0}));
}

TEST(DistanceSphereObb, TouchingFromOutsideAndWithTheCentreOnTheBoundary) {
  EXPECT_EQ(distance_sphere_obb({{1.5, 0, 0}, 0.5}, kBox).distance, 0);
  const Separation on = distance_sphere_obb({{1, 0.5, 0.5}, 0.25}, kBox);  // centre on the +x face
  EXPECT_EQ(on.distance, -0.25);
  EXPECT_EQ(on.on_b, (Vec3{1, 0.5, 0.5}));
}

TEST(DistanceSphereObb, AFlatBoxAndAPointBall) {
  const Obb plate{{0, 0, 0}, {1, 1, 0}, Mat3::identity()};
  EXPECT_EQ(distance_sphere_obb({{0.5, 0.5, 2}, 0}, plate).distance, 2);
  const Separation on = distance_sphere_obb({{0.5, 0.5, 0}, 1}, plate);
  EXPECT_EQ(on.distance, -1);  // the centre on the plate: depth 0, out through z
  EXPECT_EQ(on.on_a, (Vec3{0.5, 0.5, -1}));
}

TEST(DistanceSphereObb, RotatedBoxesAgreeWithTheAxisAlignedOne) {
  const Mat3 r = test::rotation(0.3, -1.1, 2.0);
  const Obb turned{{5, -3, 2}, kBox.half, r};
  for (const Vec3& local : {Vec3{3, 0.5, -1}, Vec3{4, 6, 0}, Vec3{-0.25, 1.75, 0}}) {
    const Vec3 world = turned.center + r * local;
    const Separation s = distance_sphere_obb({world, 0.5}, turned);
    const Separation aligned = distance_sphere_obb({local, 0.5}, kBox);
    EXPECT_NEAR(s.distance, aligned.distance, s.distance_error + aligned.distance_error);
    expect_vec(s.on_b, turned.center + r * aligned.on_b, 2 * s.point_error);
  }
}

TEST(DistanceSphereObb, OutsideTheDomainIsNaN) {
  // A negative half extent on each axis, a NaN or an infinity in each part of either shape.
  for (int i = 0; i < 3; ++i) {
    Obb flipped = kBox;
    flipped.half[i] = -flipped.half[i];
    EXPECT_TRUE(std::isnan(distance_sphere_obb({{0, 0, 0}, 1}, flipped).distance)) << i;
    Obb bad_axes = kBox;
    bad_axes.axes.col[i][2 - i] = kNan;
    EXPECT_TRUE(std::isnan(distance_sphere_obb({{0, 0, 0}, 1}, bad_axes).distance)) << i;
    Obb bad_half = kBox;
    bad_half.half[i] = HUGE_VAL;
    EXPECT_TRUE(std::isnan(distance_sphere_obb({{0, 0, 0}, 1}, bad_half).distance)) << i;
    Obb bad_center = kBox;
    bad_center.center[i] = -HUGE_VAL;
    EXPECT_TRUE(std::isnan(distance_sphere_obb({{0, 0, 0}, 1}, bad_center).distance)) << i;
  }
  EXPECT_TRUE(std::isnan(distance_sphere_obb({{kNan, 0, 0}, 1}, kBox).distance));
  EXPECT_TRUE(std::isnan(distance_sphere_obb({{0, 0, 0}, -1}, kBox).distance));
  EXPECT_TRUE(std::isnan(distance_sphere_obb({{0, 0, 0}, HUGE_VAL}, kBox).distance));
}

}  // namespace
}  // namespace cc
