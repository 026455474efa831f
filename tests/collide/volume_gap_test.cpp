// volume_gap: never more than the distance between the volumes (checked against points of both),
// the distance itself for balls and for boxes apart across a face, 0 for volumes that meet or
// touch, and 0 on NaN.
#include "collide/volume_gap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "collide/length.h"
#include "rotations.h"
#include "test_random.h"

namespace cc {
namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();

// A point of the box: centre + axes u for u in [-half, half] (corners when `corner`).
Vec3 point_of(test::Random& r, const Obb& box, bool corner) {
  Vec3 u;
  for (int i = 0; i < 3; ++i) u[i] = corner ? (r.below(2) ? box.half[i] : -box.half[i]) : r.between(-box.half[i], box.half[i]);
  return box.center + box.axes * u;
}

TEST(VolumeGap, BallsAreApartByTheirCentresLessTheRadii) {
  EXPECT_NEAR(volume_gap(Sphere{{0, 0, 0}, 1}, Sphere{{3, 4, 0}, 2}), 2.0, 1e-13);
  EXPECT_LE(volume_gap(Sphere{{0, 0, 0}, 1}, Sphere{{3, 4, 0}, 2}), 2.0);
  EXPECT_EQ(volume_gap(Sphere{{0, 0, 0}, 1}, Sphere{{3, 4, 0}, 4}), 0.0);  // touching
  EXPECT_EQ(volume_gap(Sphere{{0, 0, 0}, 1}, Sphere{{1, 1, 1}, 4}), 0.0);  // overlapping
  EXPECT_EQ(volume_gap(Sphere{{0, 0, 0}, 1}, Sphere{{1e-300, 0, 0}, 0}), 0.0);
  EXPECT_EQ(volume_gap(Sphere{{kNan, 0, 0}, 1}, Sphere{{3, 4, 0}, 2}), 0.0);
  // Far and large: the gap keeps its relative accuracy.
  const double far = volume_gap(Sphere{{0, 0, 0}, 0x1p400}, Sphere{{0x1p402, 0, 0}, 0x1p400});
  EXPECT_LE(far, 0x1p401);
  EXPECT_GE(far, 0x1p401 * (1 - 1e-13));
}

TEST(VolumeGap, BoxesApartAcrossAFaceAreApartByTheGap) {
  const Obb unit{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
  const Obb right{{4, 0.5, -0.5}, {1, 2, 3}, Mat3::identity()};
  const double g = volume_gap(unit, right);
  EXPECT_LE(g, 2.0);
  EXPECT_GE(g, 2.0 * (1 - 1e-13));
  // Turned about the x axis: still apart by 2 along x.
  const Obb turned{{4, 0, 0}, {1, 2, 3}, test::rotation(0.7, 0, 0)};
  EXPECT_NEAR(volume_gap(unit, turned), 2.0, 1e-12);
  EXPECT_EQ(volume_gap(unit, Obb{{2, 0, 0}, {1, 1, 1}, Mat3::identity()}), 0.0);  // touching face to face
  EXPECT_EQ(volume_gap(unit, Obb{{1.5, 0, 0}, {1, 1, 1}, test::rotation(0.3, 0.2, 0.1)}), 0.0);  // overlapping
  EXPECT_EQ(volume_gap(unit, Obb{{kNan, 0, 0}, {1, 1, 1}, Mat3::identity()}), 0.0);
  // Corner to corner along the diagonal: the line of centres gives most of the gap.
  const Obb diagonal{{4, 4, 4}, {1, 1, 1}, Mat3::identity()};
  EXPECT_GE(volume_gap(unit, diagonal), 0.99 * std::sqrt(3.0) * 2);
  EXPECT_LE(volume_gap(unit, diagonal), std::sqrt(3.0) * 2);
}

// Random boxes, flat ones and sheared (non-orthonormal) ones among them: the gap is never more
// than the distance between any point of one and any point of the other, and it is positive for
// some pairs (so that the check means something).
TEST(VolumeGap, NeverExceedsTheDistanceBetweenPointsOfTheBoxes) {
  test::Random r(17);
  int positive = 0, flat = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Obb box[2];
    for (Obb& b : box) {
      b.center = r.in_cube(4);
      b.half = {r.between(0, 2), r.between(0, 2), r.between(0, 2)};
      if (r.below(4) == 0) b.half[r.below(3)] = 0, ++flat;
      b.axes = test::rotation(r.between(-3, 3), r.between(-3, 3), r.between(-3, 3));
      if (r.below(4) == 0) b.axes.col[0] = b.axes.col[0] + 0.3 * b.axes.col[1];  // a parallelepiped
    }
    const double g = volume_gap(box[0], box[1]);
    ASSERT_GE(g, 0.0);
    positive += g > 0;
    for (int k = 0; k < 200; ++k) {
      const Vec3 p = point_of(r, box[0], k < 100), q = point_of(r, box[1], k < 100);
      ASSERT_LE(g, length(q - p) + 1e-13) << trial;  // the points err by about 1e-15
    }
  }
  EXPECT_GT(positive, 500);
  EXPECT_GT(flat, 100);
}

}  // namespace
}  // namespace cc
