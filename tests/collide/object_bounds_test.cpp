#include "collide/object_bounds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "collide/procedural_mesh.h"

namespace cc {
namespace {

RigidTransform random_pose(std::mt19937_64& random) {
  std::normal_distribution<double> n(0, 1);
  // A rotation from a random unit quaternion.
  double w = n(random), x = n(random), y = n(random), z = n(random);
  const double s = 1 / std::sqrt(w * w + x * x + y * y + z * z);
  w *= s, x *= s, y *= s, z *= s;
  RigidTransform t;
  t.rotation = Mat3::from_columns({1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
                                  {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
                                  {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)});
  t.translation = {100 * n(random), 100 * n(random), 100 * n(random)};
  return t;
}

bool holds(const Aabb& b, const Vec3& p) { return test_aabb_aabb(b, {p, p}); }

TEST(ObjectBounds, TheCubeAndTheFittedBoxHoldThePlacedMesh) {
  std::mt19937_64 random(5);
  const Mesh mesh = make_mesh({ProceduralMesh::Shape::torus, 1, 8, 3.0, 0, 0});
  const double radius = rotation_radius(mesh);
  for (int i = 0; i < 100; ++i) {
    const RigidTransform pose = random_pose(random);
    const Aabb cube = bounding_cube(radius, pose), fitted = fitted_box(mesh, pose);
    for (const Vec3& v : mesh.vertices) {
      const Vec3 p = apply(pose, v);
      ASSERT_TRUE(holds(cube, p));
      ASSERT_TRUE(holds(fitted, p));
    }
    // The fitted box is the tighter one, and the cube is a cube (up to the rounding of its
    // corners at the translation's magnitude).
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(fitted.hi[k] - fitted.lo[k], cube.hi[k] - cube.lo[k]);
      EXPECT_NEAR(cube.hi[k] - cube.lo[k], cube.hi[0] - cube.lo[0], 1e-12 * (cube.hi[0] - cube.lo[0]) + 1e-12 * 100);
    }
  }
}

TEST(ObjectBounds, RadiusIsTheFarthestVertex) {
  const Mesh m{{{3, 4, 0}, {0, 0, 1}, {-1, 0, 0}}, {{0, 1, 2}}};
  EXPECT_GE(rotation_radius(m), 5);
  EXPECT_LT(rotation_radius(m), 5 * (1 + 0x1p-45));
  EXPECT_EQ(rotation_radius(Mesh{}), 0);
  const RigidTransform at{Mat3::identity(), {1, 2, 3}};
  EXPECT_EQ(fitted_box(Mesh{}, at), (Aabb{{1, 2, 3}, {1, 2, 3}}));
}

}  // namespace
}  // namespace cc
