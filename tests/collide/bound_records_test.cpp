#include "collide/bound_records.h"

#include <gtest/gtest.h>

#include <cmath>

#include "collide/procedural_mesh.h"
#include "collide/ray_aabb.h"
#include "collide/triangle_box.h"
#include "collide/triangle_triangle.h"

namespace cc {
namespace {

const Mat3 kTilted = Mat3::from_columns({0.6, 0.8, 0}, {-0.8, 0.6, 0}, {0, 0, 1});

TEST(BoundRecords, RayAabbRecordsEverySlabParameter) {
  const Ray ray{{-3, 0.5, 0.25}, {2, 0.125, -0x1p-1023}};
  const Aabb box{{0, 0, 0}, {1, 1, 1}};
  bounds::Records records;
  const RayHit h = intersect_ray_aabb(ray, box, records);
  const RayHit plain = intersect_ray_aabb(ray, box);
  EXPECT_EQ(h.hit, plain.hit);
  EXPECT_EQ(h.t_enter, plain.t_enter);
  ASSERT_EQ(records.quotients.size(), 6u);  // the tiny z component takes the long double path
  for (const bounds::Quotient& q : records.quotients) {
    EXPECT_EQ(q.widening.relative, bounds::kRaySlab.relative);
    EXPECT_EQ(q.exponent, 1);  // dir scaled to [1, 2)
    const double t = (q.n1 - q.n2) / (q.d1 - q.d2) * 2;
    EXPECT_NEAR(q.t, t, 4 * fp::u * std::fabs(t)) << q.n1 << " " << q.d1;
  }
}

TEST(BoundRecords, ObbTestsRecordEveryAxisTheyTry) {
  const Obb a{{0, 0, 0}, {1, 1, 1}, Mat3::identity()}, b{{1.5, 1.5, 0}, {1, 0.5, 1}, kTilted};
  bounds::Records records;
  EXPECT_EQ(test_obb_obb(a, b, records), test_obb_obb(a, b));
  ASSERT_EQ(records.obb_tests.size(), 1u);
  EXPECT_EQ(records.obb_tests[0].bound.extent_b, 2.5);
  // Overlapping: no axis separates, so all 6 face axes and the 9 edge axes in both frames.
  ASSERT_EQ(records.obb_axes[0].size(), 24u);
  EXPECT_EQ(records.obb_axes[0][3].axis, 3);
  EXPECT_EQ(records.obb_axes[0][23].frame, 1);

  const MovingObb ma{a, {0, 0, 0}}, mb{{{5, 0, 0}, {1, 1, 1}, kTilted}, {-8, 0, 0}};
  records = {};
  EXPECT_EQ(sweep_obb_obb(ma, mb, records), sweep_obb_obb(ma, mb));
  ASSERT_EQ(records.obb_axes.size(), 1u);
  EXPECT_EQ(records.obb_axes[0].size(), 24u);
  EXPECT_EQ(records.obb_axes[0][0].rate, -8);
  EXPECT_FALSE(records.quotients.empty());
  for (const bounds::Quotient& q : records.quotients) EXPECT_EQ(q.widening.relative, bounds::kSweepObbTime.relative);
}

TEST(BoundRecords, SweepAabbRecordsItsTimes) {
  const Aabb a{{0, 0, 0}, {1, 1, 1}}, b{{3, 0, 0}, {4, 1, 1}};
  bounds::Records records;
  EXPECT_EQ(sweep_aabb_aabb(a, {0.1, 0, 0}, b, {-3, 0, 0}, records), sweep_aabb_aabb(a, {0.1, 0, 0}, b, {-3, 0, 0}));
  ASSERT_EQ(records.quotients.size(), 2u);  // the x axis only: the others have rate 0
  EXPECT_EQ(records.quotients[0].n1, 0);
  EXPECT_EQ(records.quotients[0].n2, 4);
}

TEST(BoundRecords, SpheresAndKdopsRecordTheirSquaresAndProjections) {
  const Sphere a{{0, 0, 0}, 1.5}, b{{3, 4, 0}, 3.5};
  bounds::Records records;
  EXPECT_EQ(test_sphere_sphere(a, b, records), test_sphere_sphere(a, b));
  ASSERT_EQ(records.spheres.size(), 1u);
  EXPECT_EQ(records.spheres[0].exponent, 0);  // the squares' sum in [2^-900, 2^1020]: as given
  EXPECT_EQ(records.spheres[0].bound.dist2, 25.0);
  // Beyond that range, scaled: |d| = 5 2^600 and the reach 5 2^600 brought to [1, 2).
  const Sphere huge_a{{0, 0, 0}, 0x1p600 * 1.5}, huge_b{{0x1p600 * 3, 0x1p600 * 4, 0}, 0x1p600 * 3.5};
  records = {};
  EXPECT_EQ(test_sphere_sphere(huge_a, huge_b, records), test_sphere_sphere(huge_a, huge_b));
  ASSERT_EQ(records.spheres.size(), 1u);
  EXPECT_EQ(records.spheres[0].exponent, 602);
  EXPECT_EQ(records.spheres[0].bound.dist2, 25.0 / 16);

  const std::vector<Vec3> points{{1, 2, 3}, {-1, 0.5, 2}};
  records = {};
  EXPECT_EQ(fit_kdop<18>(points, records), fit_kdop<18>(points));
  EXPECT_EQ(records.kdop_projections.size(), 12u);  // 6 two-term directions per point
  EXPECT_EQ(records.kdop_projections[0].pad, bounds::kKdopProjection * 3);  // (1, 1, 0) . (1, 2, 3)
}

TEST(BoundRecords, TriangleTestsRecordTheirAxesAndTheirChangeOfFrame) {
  const Triangle t{{Vec3{0.5, 0.5, 1}, Vec3{3, 0.5, 1}, Vec3{0.5, 3, 2}}};
  const Obb box{{0, 0, 0}, {1, 1, 1}, kTilted};
  bounds::Records records;
  EXPECT_EQ(test_triangle_obb(t, box, records), test_triangle_obb(t, box));
  ASSERT_EQ(records.frame_changes.size(), 1u);
  EXPECT_EQ(records.frame_changes[0].bound.half_sum, 3);
  EXPECT_EQ(records.sat_axes.size(), 10u);  // touching: the plane and the 9 edge axes
  EXPECT_TRUE(records.sat_axes[0].a_is_box);
  EXPECT_EQ(records.sat_axes[0].bound.perturbation_per_unit, records.frame_changes[0].bound.total());

  const Triangle u{{Vec3{0.5, 0.5, 1}, Vec3{-3, 0.5, 1}, Vec3{0.5, -3, 1}}};  // coplanar with t
  records = {};
  EXPECT_EQ(test_triangle_triangle(t, u, records), test_triangle_triangle(t, u));
  EXPECT_FALSE(records.sat_axes[0].a_is_box);
  EXPECT_FALSE(records.independences.empty());

  records = {};
  EXPECT_EQ(test_triangle_aabb(t, Aabb{{0, 0, 0}, {1, 1, 1}}, records), test_triangle_aabb(t, Aabb{{0, 0, 0}, {1, 1, 1}}));
  EXPECT_EQ(records.sat_axes.size(), 10u);
  EXPECT_EQ(records.sat_axes[0].bound.perturbation_per_unit, 0);
}

TEST(BoundRecords, RaysOnMeshesRecordTheirSlabsAndHits) {
  const Mesh mesh = make_mesh({ProceduralMesh::Shape::torus, 1, 6, 2.0, 0, 0});
  const Bvh<Obb> bvh = build_bvh<Obb>(mesh, {});
  const Ray ray{{10, 0.5, 0.25}, {-1, 0, 0}};
  bounds::Records records;
  const RayMeshHit h = ray_mesh_closest(bvh, ray, records), plain = ray_mesh_closest(bvh, ray);
  EXPECT_EQ(h.hit, plain.hit);
  EXPECT_EQ(h.t, plain.t);
  EXPECT_EQ(h.face, plain.face);
  ASSERT_FALSE(records.ray_mesh_hits.empty());
  EXPECT_EQ(records.ray_mesh_hits[0].pad.origin_norm1, 10.75);
  EXPECT_EQ(records.ray_mesh_hits[0].pad.mesh_magnitude, bvh.magnitude);
  EXPECT_FALSE(records.ray_triangle_slabs.empty());
  for (const bounds::Quotient& q : records.quotients) {
    EXPECT_EQ(q.widening.relative, bounds::kRayTriangleParameter.relative);
  }
}

TEST(BoundRecords, ObjectBoundsRecordEveryPlacementAndRoot) {
  const Mesh mesh{{{3, 4, 0}, {0, 0, 1}, {-1, 0, 0}}, {{0, 1, 2}}};
  const RigidTransform pose{kTilted, {100, -7, 0.5}};
  bounds::Records records;
  EXPECT_EQ(fitted_box(mesh, pose, records), fitted_box(mesh, pose));
  ASSERT_EQ(records.placements.size(), 3u);
  EXPECT_EQ(records.placements[0].bound.p_norm1, 7);  // the largest |v|_1
  EXPECT_EQ(records.placements[0].bound.translation, 100);
  EXPECT_EQ(records.placements[1].placed, apply(pose, mesh.vertices[1]));

  EXPECT_EQ(rotation_radius(mesh, records), rotation_radius(mesh));
  ASSERT_EQ(records.radius_roots.size(), 3u);
  EXPECT_EQ(records.radius_roots[0].root, 5);
  EXPECT_EQ(bounding_cube(5, pose, records), bounding_cube(5, pose));
  ASSERT_EQ(records.cubes.size(), 1u);
  EXPECT_EQ(records.cubes[0].bound.transform.p_norm1, 15);
}

}  // namespace
}  // namespace cc
