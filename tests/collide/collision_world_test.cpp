#include "collide/collision_world.h"

#include <gtest/gtest.h>

#include <random>

#include "collide/box_pairs.h"
#include "collide/procedural_mesh.h"

namespace cc {
namespace {


struct Scene {
  std::vector<std::shared_ptr<const Mesh>> meshes;
  std::vector<RigidTransform> poses;
};

Scene random_scene(std::uint64_t seed, int n) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const auto sphere = std::make_shared<const Mesh>(make_mesh({ProceduralMesh::Shape::sphere, 1, 5, 1.0}));
  const auto torus = std::make_shared<const Mesh>(make_mesh({ProceduralMesh::Shape::torus, 2, 5, 0.8}));
  Scene s;
  for (int i = 0; i < n; ++i) {
    s.meshes.push_back(i % 2 ? sphere : torus);
    RigidTransform t;
    const double a = 6.28 * unit(random);
    t.rotation = Mat3::from_columns({std::cos(a), std::sin(a), 0}, {-std::sin(a), std::cos(a), 0}, {0, 0, 1});
    t.translation = {8 * unit(random), 8 * unit(random), 2 * unit(random)};
    s.poses.push_back(t);
  }
  return s;
}

// Every pair of meshes tested, without boxes or sweep-and-prune.
std::vector<ObjectContact> all_pairs(const Scene& s, const std::vector<std::shared_ptr<const Bvh<Obb>>>& bvh) {
  std::vector<ObjectContact> out;
  for (ObjectId i = 0; i < s.meshes.size(); ++i) {
    for (ObjectId j = i + 1; j < s.meshes.size(); ++j) {
      CollisionResult r = collide(*bvh[i], s.poses[i], *bvh[j], s.poses[j], CollideOptions{});
      if (!r.pairs.empty()) out.push_back({{i, j}, std::move(r.pairs)});
    }
  }
  return out;
}

void expect_same(const std::vector<ObjectContact>& x, const std::vector<ObjectContact>& y) {
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(x[i].objects, y[i].objects);
    EXPECT_EQ(x[i].triangles, y[i].triangles);
  }
}

TEST(CollisionWorld, FindsTheContactsOfTestingEveryPairWithEitherBounds) {
  for (RotationBounds bounds : {RotationBounds::refit, RotationBounds::bounding_cube, RotationBounds::bounding_sphere}) {
    Scene s = random_scene(4, 40);
    std::vector<std::shared_ptr<const Bvh<Obb>>> bvh;
    for (const auto& m : s.meshes) bvh.push_back(std::make_shared<const Bvh<Obb>>(build_bvh<Obb>(*m, {})));
    CollisionWorld<Obb> world(bounds);
    for (std::size_t i = 0; i < s.meshes.size(); ++i) world.add(s.meshes[i], bvh[i], s.poses[i]);
    int colliding = 0;
    for (int frame = 0; frame < 10; ++frame) {
      for (std::size_t i = 0; i < s.meshes.size(); ++i) {
        s.poses[i].translation.x += 0.05 * static_cast<double>(i % 3) - 0.05;
        world.move(static_cast<ObjectId>(i), s.poses[i]);
      }
      const auto& candidates = world.broad_phase();
      const std::vector<ObjectContact> contacts = world.narrow_phase();
      expect_same(contacts, all_pairs(s, bvh));
      EXPECT_GE(candidates.size(), contacts.size());
      colliding += static_cast<int>(contacts.size());
    }
    EXPECT_GT(colliding, 10);  // the scene is crowded enough to test something
  }
}

TEST(CollisionWorld, RefitBoxesLeaveNoMoreCandidatesThanCubes) {
  Scene s = random_scene(9, 60);
  std::vector<std::shared_ptr<const Bvh<Obb>>> bvh;
  for (const auto& m : s.meshes) bvh.push_back(std::make_shared<const Bvh<Obb>>(build_bvh<Obb>(*m, {})));
  CollisionWorld<Obb> cube(RotationBounds::bounding_cube), refit(RotationBounds::refit);
  for (std::size_t i = 0; i < s.meshes.size(); ++i) cube.add(s.meshes[i], bvh[i], s.poses[i]), refit.add(s.meshes[i], bvh[i], s.poses[i]);
  EXPECT_LE(refit.broad_phase().size(), cube.broad_phase().size());
}

// Meshes whose vertices lie far from their own origin: their balls in their own frames are apart
// when placed together, and together when placed apart; the first level must take the placed ones.
TEST(CollisionWorld, BallsAreTestedWherePosesPlaceThem) {
  Mesh off = make_mesh({ProceduralMesh::Shape::sphere, 1, 5, 1.0});
  for (Vec3& v : off.vertices) v.x += 50;
  Mesh back = off;
  for (Vec3& v : back.vertices) v.x -= 100;
  const auto a = std::make_shared<const Mesh>(off), b = std::make_shared<const Mesh>(back);
  const auto ta = std::make_shared<const Bvh<Obb>>(build_bvh<Obb>(*a, {}));
  const auto tb = std::make_shared<const Bvh<Obb>>(build_bvh<Obb>(*b, {}));
  const Mat3 turn = Mat3::from_columns({0, 1, 0}, {-1, 0, 0}, {0, 0, 1});
  {  // placed together: a's ball moved to the origin, b's to (0.5, 0, 0)
    CollisionWorld<Obb> world(RotationBounds::bounding_sphere);
    world.add(a, ta, {turn, {0, -50, 0}});
    world.add(b, tb, {Mat3::identity(), {50.5, 0, 0}});
    ASSERT_EQ(world.broad_phase().size(), 1u);
    EXPECT_FALSE(world.narrow_phase().empty());
  }
  {  // placed apart, diagonally (their cubes overlap, their balls of radius 1 do not), though in
     // their own frames they are the same ball
    CollisionWorld<Obb> world(RotationBounds::bounding_sphere);
    world.add(a, ta, {Mat3::identity(), {0, 0, 0}});
    world.add(a, ta, {Mat3::identity(), {1.75, 1.75, 0}});
    EXPECT_TRUE(world.broad_phase().empty());
    CollisionWorld<Obb> cubes(RotationBounds::bounding_cube);
    cubes.add(a, ta, {Mat3::identity(), {0, 0, 0}});
    cubes.add(a, ta, {Mat3::identity(), {1.75, 1.75, 0}});
    EXPECT_EQ(cubes.broad_phase().size(), 1u);  // (the cubes around the meshes' origins meet)
  }
}

TEST(CollisionWorld, ARemovedObjectCollidesNoMore) {
  Scene s = random_scene(4, 20);
  std::vector<std::shared_ptr<const Bvh<Obb>>> bvh;
  for (const auto& m : s.meshes) bvh.push_back(std::make_shared<const Bvh<Obb>>(build_bvh<Obb>(*m, {})));
  CollisionWorld<Obb> world;
  for (std::size_t i = 0; i < s.meshes.size(); ++i) world.add(s.meshes[i], bvh[i], s.poses[i]);
  world.broad_phase();
  const std::vector<ObjectContact> before = world.narrow_phase();
  ASSERT_FALSE(before.empty());
  const ObjectId gone = before[0].objects.first;
  world.remove(gone);
  world.broad_phase();
  for (const ObjectContact& c : world.narrow_phase()) {
    EXPECT_NE(c.objects.first, gone);
    EXPECT_NE(c.objects.second, gone);
  }
}

}  // namespace
}  // namespace cc
