// The cost function of a mesh query: its counters are the query's own, its unit costs are
// measured (positive, finite), and T is the sum the model says.
#include "harness/judging/query_cost.h"

#include <gtest/gtest.h>

#include <cmath>

#include "harness/model/mesh_collide.h"

namespace cc::harness {
namespace {

MeshPair spheres(BvType bv, BvUpdate update) {
  MeshPair m;
  m.a = procedural_mesh({ProceduralMesh::Shape::sphere, 1, 10, 1.0});
  m.b = procedural_mesh({ProceduralMesh::Shape::torus, 2, 10, 1.0});
  m.pose_b.rotation = Mat3::from_columns({0, 1, 0}, {-1, 0, 0}, {0, 0, 1});
  m.pose_b.translation = {0.5, 0.25, 0.125};
  m.library.bv = bv;
  m.library.update = update;
  return m;
}

TEST(QueryCost, CountsTheQueryAndSumsTheModel) {
  for (BvType bv : {BvType::obb, BvType::aabb, BvType::kdop18}) {
    for (BvUpdate update : {BvUpdate::approximate, BvUpdate::exact}) {
      const MeshPair m = spheres(bv, update);
      const QueryCost c = measure_query_cost(m, CollisionMode::all_pairs, 3);
      SCOPED_TRACE(std::string(to_string(bv)) + " " + std::string(to_string(update)));
      EXPECT_EQ(c.counters, library_collide(m, CollisionMode::all_pairs).counters);
      EXPECT_GT(c.counters.bv_tests, 0u);
      EXPECT_GT(c.counters.primitive_tests, 0u);
      EXPECT_EQ(c.counters.bv_updates > 0, bv != BvType::obb);  // an OBB moves without a refit
      for (double unit : {c.unit.bv_test, c.unit.primitive_test, c.unit.bv_update}) {
        EXPECT_TRUE(std::isfinite(unit) && unit > 0) << unit;
      }
      const double t = static_cast<double>(c.counters.bv_tests) * c.unit.bv_test +
                       static_cast<double>(c.counters.primitive_tests) * c.unit.primitive_test +
                       static_cast<double>(c.counters.bv_updates) * c.unit.bv_update;
      EXPECT_DOUBLE_EQ(c.predicted_ns, t);
      EXPECT_GT(c.measured_ns, 0);
    }
  }
}

TEST(QueryCost, AFirstHitCostsNoMoreThanAllPairs) {
  const MeshPair m = spheres(BvType::aabb, BvUpdate::approximate);
  const CollisionCounters first = measure_query_cost(m, CollisionMode::first_hit, 1).counters;
  const CollisionCounters all = measure_query_cost(m, CollisionMode::all_pairs, 1).counters;
  EXPECT_LE(first.bv_tests, all.bv_tests);
  EXPECT_LE(first.primitive_tests, all.primitive_tests);
  EXPECT_LT(first.primitive_tests + first.bv_tests, all.primitive_tests + all.bv_tests);
}

TEST(QueryCost, EmptyMeshesCostNothing) {
  MeshPair m = spheres(BvType::obb, BvUpdate::approximate);
  m.b = triangles_mesh({});
  const UnitCosts u = measure_unit_costs(m, 1);
  EXPECT_EQ(u.bv_test, 0);
  EXPECT_EQ(u.primitive_test, 0);
}

}  // namespace
}  // namespace cc::harness
