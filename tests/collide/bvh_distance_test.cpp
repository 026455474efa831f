// distance() on Obb and sphere trees against distance_brute_force: the same distance within
// their errors for every build and pose (apart, touching, crossing, one mesh inside another),
// witnesses on the faces they name, pruning that skips most pairs of meshes far apart, swapping
// the meshes, and the answers outside the domain and for a mesh without triangles.
// tests/collide_exact/bvh_distance_test.cpp checks the bound in rationals.
#include "collide/bvh_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "collide/bvh_collide.h"
#include "collide/procedural_mesh.h"
#include "collide/triangle_distance.h"
#include "rotations.h"

namespace cc {
namespace {

using Shape = ProceduralMesh::Shape;

Mesh square(double z) {  // the unit square [0, 1]^2 at height z, two triangles
  Mesh m;
  m.vertices = {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}};
  m.faces = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

const std::vector<RigidTransform> kPoses = {
    {Mat3::identity(), {0, 0, 0}},
    {test::rotation(0.3, -1.2, 2.0), {0.4, 0.1, -0.2}},
    {test::rotation(3.0, 0.5, -0.7), {1.1, -0.6, 0.3}},
    {test::rotation(-2.2, 2.9, 0.1), {1.9, 0.2, 0.0}},
    {test::rotation(1.0, 1.0, 1.0), {5, 5, 5}},  // apart
    {test::rotation(0.1, 0.0, 0.4), {0, 0, 2.6}},  // apart by a little
};

// How far a point lies from a placed face of a mesh at least (the lower end of the triangle
// distance's answer; the collide_exact test measures it exactly).
double distance_to_face(const Vec3& p, const Mesh& mesh, std::uint32_t face, const RigidTransform& pose) {
  const Triangle t = mesh.triangle(face);
  const Triangle placed{{apply(pose, t.v[0]), apply(pose, t.v[1]), apply(pose, t.v[2])}};
  const Separation s = distance_triangle_triangle({{p, p, p}}, placed);
  return s.distance - s.distance_error;
}

void expect_agrees(const MeshSeparation& got, const MeshSeparation& brute, const Mesh& a, const RigidTransform& pose_a,
                   const Mesh& b, const RigidTransform& pose_b) {
  const Separation& s = got.separation;
  ASSERT_NE(got.faces.first, kNoFace);
  EXPECT_GE(s.distance, 0);
  EXPECT_NEAR(s.distance, brute.separation.distance, s.distance_error + brute.separation.distance_error);
  EXPECT_LE(s.distance_error, 0x1p-40);  // unit-sized meshes
  EXPECT_LE(distance_to_face(s.on_a, a, got.faces.first, pose_a), s.point_error);
  EXPECT_LE(distance_to_face(s.on_b, b, got.faces.second, pose_b), s.point_error);
  EXPECT_NEAR(length(s.on_b - s.on_a), s.distance, 2 * s.point_error + s.distance_error);
}

template <class BV>
class BvhDistanceTest : public ::testing::Test {};
using VolumeTypes = ::testing::Types<Obb, Sphere>;
TYPED_TEST_SUITE(BvhDistanceTest, VolumeTypes);

TYPED_TEST(BvhDistanceTest, EveryBuildAgreesWithBruteForce) {
  const Mesh torus = make_mesh({Shape::torus, 0, 6, 1.0});
  const Mesh soup = make_mesh({Shape::soup, 11, 80, 1.0, 0, 15});
  const RigidTransform place_torus{test::rotation(0.2, 0.1, 0.0), {0.1, 0, 0}};
  int apart = 0, meeting = 0;
  for (const BuildOptions& build : {BuildOptions{}, BuildOptions{BuildStrategy::top_down, SplitAxis::min_sum, SplitPoint::mean, 4},
                                    BuildOptions{BuildStrategy::bottom_up}, BuildOptions{BuildStrategy::incremental}}) {
    const Bvh<TypeParam> a = build_bvh<TypeParam>(torus, build), b = build_bvh<TypeParam>(soup, build);
    for (const RigidTransform& pose : kPoses) {
      const MeshSeparation brute = distance_brute_force(torus, place_torus, soup, pose);
      const MeshSeparation got = distance(a, place_torus, b, pose);
      expect_agrees(got, brute, torus, place_torus, soup, pose);
      EXPECT_LE(got.counters.primitive_tests, torus.size() * soup.size());
      EXPECT_GE(got.counters.bv_tests, 1u);
      // Meshes that share a point (collide() finds a pair) are at 0.
      const bool collide_pairs = !collide(a, place_torus, b, pose, {}).pairs.empty();
      if (collide_pairs) {
        EXPECT_LE(got.separation.distance, got.separation.distance_error);
      }
      (got.separation.distance > 0.01 ? apart : meeting) += 1;
    }
  }
  EXPECT_GT(apart, 4);
  EXPECT_GT(meeting, 4);
}

TYPED_TEST(BvhDistanceTest, MeshesFarApartPruneMostPairs) {
  const Mesh sphere = make_mesh({Shape::sphere, 0, 16, 1.0});
  const Bvh<TypeParam> a = build_bvh<TypeParam>(sphere, {}), b = build_bvh<TypeParam>(sphere, {});
  const RigidTransform far{test::rotation(0.4, 0.5, 0.6), {5, 1, 0}};
  const MeshSeparation got = distance(a, {}, b, far);
  const MeshSeparation brute = distance_brute_force(sphere, {}, sphere, far);
  expect_agrees(got, brute, sphere, {}, sphere, far);
  EXPECT_NEAR(got.separation.distance, std::sqrt(26.0) - 2, 0.05);  // two polygonal unit spheres
  EXPECT_LT(got.counters.primitive_tests * 50, sphere.size() * sphere.size());
}

TYPED_TEST(BvhDistanceTest, ParallelSquaresAreApartByTheirHeight) {
  const Mesh lower = square(0), upper = square(0);
  const Bvh<TypeParam> a = build_bvh<TypeParam>(lower, {}), b = build_bvh<TypeParam>(upper, {});
  for (const double h : {0.5, 1e-6, 0x1p-40, 0.0}) {
    const RigidTransform above{Mat3::identity(), {0.25, 0.5, h}};
    const Separation s = distance(a, {}, b, above).separation;
    EXPECT_NEAR(s.distance, h, s.distance_error) << h;
    EXPECT_LE(s.distance_error, 0x1p-44) << h;  // 2^-50 of the vertices' and translation's size, and more
  }
  // Standing on a's edge, and turned a quarter about z: touching, then apart by the height.
  EXPECT_EQ(distance(a, {}, b, {test::rotation(M_PI / 2, 0, 0), {0, 0, 0}}).separation.distance, 0.0);
  const Separation turned = distance(a, {}, b, {test::rotation(0, M_PI / 2, 0), {0.5, 0, 0.25}}).separation;
  EXPECT_NEAR(turned.distance, 0.25, turned.distance_error);
}

TYPED_TEST(BvhDistanceTest, AMeshInsideAnotherIsApartByTheGapBetweenTheSurfaces) {
  const Mesh big = make_mesh({Shape::sphere, 0, 12, 10.0}), small = make_mesh({Shape::sphere, 0, 8, 1.0});
  const Bvh<TypeParam> a = build_bvh<TypeParam>(big, {}), b = build_bvh<TypeParam>(small, {});
  const RigidTransform off{test::rotation(0.3, 0.2, 0.1), {2, 0, 0}};
  const MeshSeparation got = distance(a, {}, b, off);
  expect_agrees(got, distance_brute_force(big, {}, small, off), big, {}, small, off);
  EXPECT_GT(got.separation.distance, 6.0);
  EXPECT_LT(got.separation.distance, 7.0);
}

TYPED_TEST(BvhDistanceTest, SwappingTheMeshesSwapsTheFaces) {
  const Mesh sphere = make_mesh({Shape::sphere, 0, 6, 1.0});
  const Mesh plate = make_mesh({Shape::plate, 0, 4, 1.2, 0.01});
  const Bvh<TypeParam> s = build_bvh<TypeParam>(sphere, {}), p = build_bvh<TypeParam>(plate, {});
  const RigidTransform a{test::rotation(0.1, 0.2, 0.3), {0, 0, 1.5}}, b{test::rotation(-0.5, 0.4, 0.0), {0.3, 0, 0}};
  const MeshSeparation forward = distance(s, a, p, b), backward = distance(p, b, s, a);
  EXPECT_NEAR(forward.separation.distance, backward.separation.distance,
              forward.separation.distance_error + backward.separation.distance_error);
  EXPECT_GT(forward.separation.distance, 0.1);
  expect_agrees(backward, distance_brute_force(plate, b, sphere, a), plate, b, sphere, a);
}

TYPED_TEST(BvhDistanceTest, OutsideTheDomainAndWithoutTriangles) {
  const Mesh sphere = make_mesh({Shape::sphere, 0, 4, 1.0});
  const Bvh<TypeParam> s = build_bvh<TypeParam>(sphere, {});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const RigidTransform& bad : {RigidTransform{Mat3::identity(), {nan, 0, 0}}, RigidTransform{Mat3::identity(), {0x1p301, 0, 0}},
                                    RigidTransform{Mat3::identity(), {INFINITY, 0, 0}}}) {
    const MeshSeparation got = distance(s, {}, s, bad);
    EXPECT_TRUE(std::isnan(got.separation.distance));
    EXPECT_EQ(got.separation.distance_error, INFINITY);
    EXPECT_EQ(got.faces.first, kNoFace);
    EXPECT_TRUE(std::isnan(distance_brute_force(sphere, bad, sphere, {}).separation.distance));
  }
  const Bvh<TypeParam> empty = build_bvh<TypeParam>(Mesh{}, {});
  const MeshSeparation none = distance(s, {}, empty, {});
  EXPECT_EQ(none.separation.distance, INFINITY);
  EXPECT_EQ(none.faces, std::make_pair(kNoFace, kNoFace));
  EXPECT_EQ(none.separation.distance_error, 0.0);
  EXPECT_EQ(distance_brute_force(Mesh{}, {}, sphere, {}).separation.distance, INFINITY);
}

}  // namespace
}  // namespace cc
