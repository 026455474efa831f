#include "collide/ray_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "collide/procedural_mesh.h"
#include "collide/seeded_random.h"

namespace cc {
namespace {

using Shape = ProceduralMesh::Shape;

template <class BV>
class RayMeshTest : public ::testing::Test {};
using VolumeTypes = ::testing::Types<Aabb, Obb, Kdop<6>, Kdop<14>, Kdop<16>, Kdop<18>, Kdop<24>, Kdop<26>, Sphere>;
TYPED_TEST_SUITE(RayMeshTest, VolumeTypes);

const std::vector<BuildOptions> kBuilds = {
    BuildOptions{},
    BuildOptions{BuildStrategy::top_down, SplitAxis::splatter, SplitPoint::median, 3},
    BuildOptions{BuildStrategy::top_down, SplitAxis::min_sum, SplitPoint::mean, 4},
    BuildOptions{BuildStrategy::bottom_up},
    BuildOptions{BuildStrategy::incremental},
};

std::string describe(const Ray& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "ray o=(%a,%a,%a) d=(%a,%a,%a) t=[%a,%a]", r.origin.x, r.origin.y, r.origin.z, r.dir.x,
                r.dir.y, r.dir.z, r.tmin, r.tmax);
  return buf;
}

using Random = SeededRandom;

Vec3 in_cube(Random& random, double h) { return {random.between(-h, h), random.between(-h, h), random.between(-h, h)}; }

// Rays of every kind the traversal must get right, for a mesh of about unit size around the
// origin: random ones, ones aimed at a face's vertex or edge (shared with its neighbours: ties),
// rays starting inside, rays pointing away, segments ending early, lines, and rays in the
// plane z = 0 (in the plane of a flat plate's faces).
std::vector<Ray> rays_for(const Mesh& mesh, std::uint64_t seed, int count) {
  Random random(seed);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const Triangle tri = mesh.triangle(random.below(mesh.size()));
    Vec3 target;
    switch (random.below(4)) {
      case 0: target = in_cube(random, 1); break;
      case 1: target = tri.v[random.below(3)]; break;
      case 2: target = 0.5 * (tri.v[0] + tri.v[1]); break;
      default: target = (1.0 / 3) * (tri.v[0] + tri.v[1] + tri.v[2]); break;
    }
    Ray r{in_cube(random, 3), {}, 0, INFINITY};
    switch (i % 8) {
      case 0: r.origin = in_cube(random, 0.2); break;  // inside (a sphere's, a torus's hole)
      case 1: r.tmax = random.between(0, 1); break;    // may end before the mesh
      case 2: r.tmin = -INFINITY; break;                // a line
      case 3: r.origin.z = target.z = 0; break;         // in the plane z = 0
      case 4: r.tmin = random.between(0, 1), r.tmax = random.between(1, 2); break;
      default: break;
    }
    r.dir = target - r.origin;
    if (i % 8 == 5) r.dir = -1.0 * r.dir;  // pointing away: most miss
    if (i % 8 == 6) r.dir = std::ldexp(1.0, static_cast<int>(random.below(60)) - 30) * r.dir;
    rays.push_back(r);
  }
  return rays;
}

std::vector<Mesh> test_meshes() {
  return {
      make_mesh({Shape::sphere, 0, 8, 1.0}),
      make_mesh({Shape::torus, 0, 8, 1.0}),
      make_mesh({Shape::terrain, 3, 8, 1.0}),
      make_mesh({Shape::plate, 0, 4, 1.0, 0.0}),  // flat and two-sided: every hit is a tie
      make_mesh({Shape::plate, 0, 3, 1.0, 0.2}),
      make_mesh({Shape::soup, 11, 80, 1.0, 0, 15}),  // with segments and points
  };
}

TYPED_TEST(RayMeshTest, ClosestHitIsTheBruteForceOneForEveryBuild) {
  const std::vector<Mesh> meshes = test_meshes();
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = meshes[m];
    const std::vector<Ray> rays = rays_for(mesh, 100 + m, 300);
    std::vector<RayMeshHit> expected;
    for (const Ray& r : rays) expected.push_back(ray_mesh_brute_force(mesh, r));
    for (const BuildOptions& build : kBuilds) {
      SCOPED_TRACE("mesh " + std::to_string(m) + ", " + std::string(to_string(build.strategy)) + " " +
                   std::string(to_string(build.axis)));
      const Bvh<TypeParam> bvh = build_bvh<TypeParam>(mesh, build);
      int hits = 0;
      for (std::size_t i = 0; i < rays.size(); ++i) {
        const RayMeshHit closest = ray_mesh_closest(bvh, rays[i]);
        ASSERT_EQ(closest.hit, expected[i].hit) << describe(rays[i]);
        EXPECT_LE(closest.counters.triangle_tests, mesh.size());
        EXPECT_GE(closest.counters.bv_tests, 1u);
        const RayMeshHit any = ray_mesh_any(bvh, rays[i]);
        ASSERT_EQ(any.hit, expected[i].hit) << describe(rays[i]);
        // Before its first hit the any-hit traversal visits what the closest-hit one does.
        EXPECT_LE(any.counters.triangle_tests, closest.counters.triangle_tests);
        EXPECT_LE(any.counters.bv_tests, closest.counters.bv_tests);
        if (!closest.hit) continue;
        ++hits;
        EXPECT_EQ(closest.t, expected[i].t) << describe(rays[i]);
        EXPECT_EQ(closest.face, expected[i].face) << describe(rays[i]);
        // The any hit is a real hit of its face, at that face's t, no earlier than the closest.
        const RayTriangleHit own = intersect_ray_triangle(rays[i], mesh.triangle(any.face));
        EXPECT_TRUE(own.hit);
        EXPECT_EQ(any.t, own.t);
        EXPECT_GE(any.t, closest.t);
      }
      EXPECT_GT(hits, 30);
    }
  }
}

TYPED_TEST(RayMeshTest, VolumeEntriesBoundTheirTrianglesHits) {
  // The pruning invariant, node by node: a triangle hit at t lies below a node whose entry is
  // a hit at most t.
  const Mesh soup = make_mesh({Shape::soup, 5, 60, 1.0, 0, 10});
  const Mesh terrain = make_mesh({Shape::terrain, 8, 6, 1.0});
  for (const Mesh* mesh : {&soup, &terrain}) {
    const Bvh<TypeParam> bvh = build_bvh<TypeParam>(*mesh, {BuildStrategy::top_down, SplitAxis::min_max, SplitPoint::mean, 2});
    for (const Ray& r : rays_for(*mesh, 7, 200)) {
      const double pad = ray_mesh_pad(bvh, r);
      for (std::size_t n = 0; n < bvh.nodes.size(); ++n) {
        const BvhNode<TypeParam>& node = bvh.nodes[n];
        const RayVolumeEntry entry = ray_volume_entry(node.bv, r, pad);
        for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
          const RayTriangleHit h = intersect_ray_triangle(r, bvh.triangle(s));
          if (!h.hit) continue;
          ASSERT_TRUE(entry.hit) << "node " << n << " slot " << s << " " << describe(r);
          ASSERT_LE(entry.t, h.t) << "node " << n << " slot " << s << " " << describe(r);
          ASSERT_GE(entry.t, r.tmin);
        }
      }
    }
  }
}

TYPED_TEST(RayMeshTest, TheHierarchyPrunes) {
  // Hitting rays from outside a finely tessellated sphere test a few dozen of its triangles.
  const Mesh sphere = make_mesh({Shape::sphere, 0, 24, 1.0});
  const Bvh<TypeParam> bvh = build_bvh<TypeParam>(sphere, {});
  Random random(3);
  std::uint64_t tests = 0;
  int hits = 0;
  for (int i = 0; i < 100; ++i) {
    const Vec3 origin = 3.0 * Vec3{random.between(-1, 1), random.between(-1, 1), 1};
    const RayMeshHit h = ray_mesh_closest(bvh, {origin, in_cube(random, 0.5) - origin, 0, INFINITY});
    if (!h.hit) continue;
    ++hits;
    tests += h.counters.triangle_tests;
  }
  ASSERT_GT(hits, 50);
  EXPECT_LT(tests, 50u * static_cast<std::uint64_t>(hits)) << "of " << sphere.size() << " triangles";
}

TYPED_TEST(RayMeshTest, EmptyMeshesAndBadRaysGiveNoHit) {
  const Bvh<TypeParam> empty = build_bvh<TypeParam>(Mesh{}, {});
  const Ray down{{0, 0, 2}, {0, 0, -1}, 0, INFINITY};
  EXPECT_FALSE(ray_mesh_closest(empty, down).hit);
  EXPECT_FALSE(ray_mesh_any(empty, down).hit);
  EXPECT_EQ(ray_mesh_closest(empty, down).counters, RayMeshCounters{});

  const Mesh sphere = make_mesh({Shape::sphere, 0, 6, 1.0});
  const Bvh<TypeParam> bvh = build_bvh<TypeParam>(sphere, {});
  ASSERT_TRUE(ray_mesh_closest(bvh, down).hit);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Ray& bad : {Ray{{nan, 0, 2}, {0, 0, -1}, 0, INFINITY}, Ray{{0, 0, 2}, {0, nan, -1}, 0, INFINITY},
                         Ray{{0, 0, 2}, {0, 0, -1}, nan, INFINITY}, Ray{{0, 0, 2}, {0, 0, -1}, 2, 1},
                         Ray{{0, 0, INFINITY}, {0, 0, -1}, 0, INFINITY}}) {
    EXPECT_FALSE(ray_mesh_closest(bvh, bad).hit);
    EXPECT_FALSE(ray_mesh_any(bvh, bad).hit);
    EXPECT_FALSE(ray_mesh_brute_force(sphere, bad).hit);
  }
}

// Two unit squares [0, 1]^2, at z = 0 (faces 0, 1) and at z = 1 (faces 2, 3).
Mesh two_squares() {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  m.faces = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  return m;
}

TYPED_TEST(RayMeshTest, HandMadeHits) {
  const Mesh squares = two_squares();
  const Bvh<TypeParam> bvh = build_bvh<TypeParam>(squares, {});
  const auto closest = [&](const Ray& r) { return ray_mesh_closest(bvh, r); };
  // Down through both: the upper square first (face 2: x > y), at t = 1.
  RayMeshHit h = closest({{0.75, 0.25, 2}, {0, 0, -1}, 0, INFINITY});
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.face, 2u);
  EXPECT_NEAR(h.t, 1, 1e-12);
  EXPECT_LE(h.t, 1);
  // Starting between them, or past the upper one: the lower square at t = 2.
  h = closest({{0.25, 0.75, 2}, {0, 0, -1}, 1.5, INFINITY});
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.face, 1u);
  EXPECT_NEAR(h.t, 2, 1e-12);
  // Ending before the upper square: nothing.
  EXPECT_FALSE(closest({{0.75, 0.25, 2}, {0, 0, -1}, 0, 0.999}).hit);
  // Through the diagonal both triangles share: either, as brute force decides (the smaller t,
  // then the smaller face).
  const Ray diagonal{{0.5, 0.5, 2}, {0, 0, -1}, 0, INFINITY};
  h = closest(diagonal);
  ASSERT_TRUE(h.hit);
  EXPECT_TRUE(h.face == 2 || h.face == 3);
  EXPECT_EQ(h.face, ray_mesh_brute_force(squares, diagonal).face);
  // In the plane of the lower square along y = 0.5: it enters face 1 (y >= x) at x = 0.
  h = closest({{-1, 0.5, 0}, {1, 0, 0}, 0, INFINITY});
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.face, 1u);
  EXPECT_NEAR(h.t, 1, 1e-12);
  // Pointing away, and passing beside them.
  EXPECT_FALSE(closest({{0.5, 0.5, 2}, {0, 0, 1}, 0, INFINITY}).hit);
  EXPECT_FALSE(closest({{1.5, 0.5, 2}, {0, 0, -1}, 0, INFINITY}).hit);
  EXPECT_TRUE(ray_mesh_any(bvh, {{0.5, 0.5, -1}, {0, 0, 1}, 0, INFINITY}).hit);
}

TEST(RayVolumeEntry, ObbInItsOwnFrame) {
  // The unit cube turned 45 degrees about z: in the plane z = 0 a square with corners on the axes.
  const double c = std::sqrt(0.5);
  Obb box{{0, 0, 0}, {0.5, 0.5, 0.5}, Mat3::from_columns({c, c, 0}, {-c, c, 0}, {0, 0, 1})};
  const double corner = std::sqrt(0.5);  // the box reaches x = +-corner
  const RayVolumeEntry through = ray_volume_entry(box, {{-2, 0, 0}, {1, 0, 0}, 0, INFINITY}, 0);
  ASSERT_TRUE(through.hit);
  EXPECT_NEAR(through.t, 2 - corner, 1e-12);
  EXPECT_FALSE(ray_volume_entry(box, {{-2, corner + 1e-9, 0}, {1, 0, 0}, 0, INFINITY}, 0).hit);
  EXPECT_TRUE(ray_volume_entry(box, {{-2, corner + 1e-9, 0}, {1, 0, 0}, 0, INFINITY}, 1e-8).hit);  // the pad
  EXPECT_FALSE(ray_volume_entry(box, {{-2, 0, 0}, {-1, 0, 0}, 0, INFINITY}, 0).hit);
  EXPECT_FALSE(ray_volume_entry(box, {{-2, 0, 0}, {1, 0, 0}, 0, 1}, 0).hit);
}

TEST(RayVolumeEntry, KdopSlabsAndParallelOnes) {
  const std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // a corner of a cube
  const Kdop<14> dop = fit_kdop<14>(points);  // its diagonal slab x + y + z <= 1 cuts the corner
  const RayVolumeEntry h = ray_volume_entry(dop, {{2, 2, 2}, {-1, -1, -1}, 0, INFINITY}, 0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 2 - 1.0 / 3, 1e-12);  // enters through x + y + z = 1
  // Parallel to the diagonal slab (x + y + z constant) just outside it: a miss; inside: a hit.
  EXPECT_FALSE(ray_volume_entry(dop, {{0.6, 0.6, 0.05}, {1, -1, 0}, -INFINITY, INFINITY}, 0).hit);
  EXPECT_TRUE(ray_volume_entry(dop, {{0.5, 0.4, 0}, {1, -1, 0}, -INFINITY, INFINITY}, 0).hit);
  EXPECT_FALSE(ray_volume_entry(Kdop<14>{}, {{0, 0, 0}, {1, 0, 0}, 0, INFINITY}, 1).hit);  // empty
}

}  // namespace
}  // namespace cc
