// The touching constructions of harness/generation/touch.h taken one at a time, at the poses the
// property tests rarely draw (tests/properties/touch_properties.cpp covers every kind's).
#include "harness/generation/touch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "harness/generation/mesh_poses.h"

namespace cc::harness {
namespace {

// The distance (largest coordinate difference) from the nearest vertex of b, placed, to a vertex of a, placed.
double nearest_vertex_gap(const MeshPair& m) {
  double best = std::numeric_limits<double>::infinity();
  for (const Vec3& va : m.a.mesh->vertices) {
    for (const Vec3& vb : m.b.mesh->vertices) best = std::min(best, max_abs(apply(m.pose_a, va) - apply(m.pose_b, vb)));
  }
  return best;
}

// However far b's old translation is, the vertices meet within a few roundings of the meshes'
// own scale (about 1 here): the new translation is computed from b's vertex turned alone, never
// through the old one, whose ULPs (2^8 at 2^60) would push the vertices apart.
TEST(TouchAtVertices, MeetsWithinRoundingsOfTheMeshesWhereverBWas) {
  RandomChoices c(5);
  for (const double far : {0.0, 0x1p20, 0x1p60, -0x1p200}) {
    for (int i = 0; i < 20; ++i) {
      MeshPair m;
      m.a = procedural_mesh({ProceduralMesh::Shape::sphere, 1, 6, 1.0});
      m.b = procedural_mesh({ProceduralMesh::Shape::terrain, static_cast<std::uint64_t>(i), 6, 0.5});
      m.pose_a = fcl_style_pose(c);
      m.pose_a.translation = {};
      m.pose_b = fcl_style_pose(c);
      m.pose_b.translation = {far, -far, 0.5 * far};
      touch_at_vertices(m, c);
      EXPECT_LE(nearest_vertex_gap(m), 0x1p-48) << "b first at " << far;
    }
  }
}

}  // namespace
}  // namespace cc::harness
