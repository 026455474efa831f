#include "collide/mesh_contacts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "collide/bvh_collide.h"
#include "collide/procedural_mesh.h"

namespace cc {
namespace {

// A square of two triangles in z = 0, from (0, 0) to (4, 4).
const Mesh kSquare{{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}}, {{0, 1, 2}, {0, 2, 3}}};
// A triangle standing in the plane x = 1, crossing z = 0 from y = 0.5 to y = 1.5 (placed by its pose).
const Mesh kFin{{{0, 0, -1}, {0, 2, 1}, {0, -0, 1}}, {{0, 1, 2}}};

std::vector<Vec3> corners(const PairContact& c) { return {c.corners.points.begin(), c.corners.points.begin() + c.corners.count}; }

TEST(MeshContacts, EachPairGetsTheCornersOfItsTrianglesAsMoved) {
  const RigidTransform identity{Mat3::identity(), {0, 0, 0}};
  const RigidTransform fin_pose{Mat3::identity(), {1, 0.5, 0}};
  const auto pairs = collide_brute_force(kSquare, identity, kFin, fin_pose);
  ASSERT_EQ(pairs.size(), 2u);  // the fin crosses the square's diagonal: both triangles
  const std::vector<PairContact> contacts = mesh_contacts(kSquare, identity, kFin, fin_pose, pairs);
  ASSERT_EQ(contacts.size(), 2u);
  std::vector<Vec3> all;
  for (const PairContact& c : contacts) {
    EXPECT_EQ(c.corners.count, 2) << c.face_a;
    for (const Vec3& p : corners(c)) {
      EXPECT_EQ(p.x, 1);
      EXPECT_EQ(p.z, 0);
      all.push_back(p);
    }
  }
  // Together: x = 1, z = 0 from y = 0.5 to y = 1.5, split at the diagonal y = x.
  std::sort(all.begin(), all.end(), [](const Vec3& a, const Vec3& b) { return a.y < b.y; });
  EXPECT_EQ(all.front().y, 0.5);
  EXPECT_EQ(all[1].y, 1);
  EXPECT_EQ(all[2].y, 1);
  EXPECT_EQ(all.back().y, 1.5);
}

TEST(MeshContacts, TheCornersAreInAsFrame) {
  // The square turned a quarter about z and moved: the corners come back in its own frame.
  const RigidTransform turned{Mat3::from_columns({0, 1, 0}, {-1, 0, 0}, {0, 0, 1}), {10, 0, 0}};
  // The fin placed in the world where the turned square's x = 1 is: world x = 10 - y_a, world y = x_a.
  const RigidTransform fin_pose{Mat3::from_columns({0, 1, 0}, {-1, 0, 0}, {0, 0, 1}), {10, 1, 0}};
  const auto pairs = collide_brute_force(kSquare, turned, kFin, fin_pose);
  ASSERT_FALSE(pairs.empty());
  for (const PairContact& c : mesh_contacts(kSquare, turned, kFin, fin_pose, pairs)) {
    for (const Vec3& p : corners(c)) {
      EXPECT_EQ(p.x, 1);  // in a's frame
      EXPECT_EQ(p.z, 0);
      const Vec3 world = apply(turned, p);
      EXPECT_EQ(world.y, 1);
    }
  }
}

TEST(MeshContacts, EveryPairOfCollideGetsCornersOnMeshesThatCross) {
  ProceduralMesh big{ProceduralMesh::Shape::sphere, 1, 12, 1.0}, small{ProceduralMesh::Shape::torus, 2, 10, 0.7};
  const Mesh a = make_mesh(big), b = make_mesh(small);
  const RigidTransform pose_a{Mat3::identity(), {0, 0, 0}}, pose_b{Mat3::identity(), {1.1, 0.3, 0.2}};
  const Bvh<Obb> ta = build_bvh<Obb>(a, {}), tb = build_bvh<Obb>(b, {});
  const CollisionResult r = collide(ta, pose_a, tb, pose_b, {});
  ASSERT_GT(r.pairs.size(), 10u);
  const std::vector<PairContact> contacts = mesh_contacts(a, pose_a, b, pose_b, r.pairs);
  ASSERT_EQ(contacts.size(), r.pairs.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    EXPECT_EQ(std::pair(contacts[i].face_a, contacts[i].face_b), r.pairs[i]);
    EXPECT_FALSE(contacts[i].corners.empty()) << i;  // generic crossings: no pair within the band only
  }
}

}  // namespace
}  // namespace cc
