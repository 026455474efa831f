// Poses for mesh queries: FCL's distribution, and bisection to first contact.
#include "harness/generation/mesh_poses.h"

#include <gtest/gtest.h>

#include <cmath>

#include "harness/model/mesh_collide.h"
#include "oracle/exact/exact_meshes.h"

namespace cc::harness {
namespace {

TEST(FclStylePose, IsARotationAndATranslationInFclsRange) {
  RandomChoices c(3);
  for (int i = 0; i < 200; ++i) {
    const RigidTransform t = fcl_style_pose(c);
    const Mat3& r = t.rotation;
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(dot(r.col[j], r.col[k]), j == k ? 1 : 0, 1e-14);
    }
    EXPECT_GT(dot(cross(r.col[0], r.col[1]), r.col[2]), 0);  // proper
    EXPECT_LE(std::fabs(t.translation.x), 3000);
    EXPECT_LE(std::fabs(t.translation.y), 3000);
    EXPECT_GE(t.translation.z, 0);
    EXPECT_LE(t.translation.z, 3000);
  }
}

TEST(BisectToContact, EndsWithinAFewUlpsOfFirstContact) {
  RandomChoices c(11);
  int bisected = 0;
  for (int i = 0; i < 20; ++i) {
    MeshPair m;
    m.a = procedural_mesh({ProceduralMesh::Shape::sphere, 1, 6, 1.0});
    m.b = procedural_mesh({ProceduralMesh::Shape::terrain, static_cast<std::uint64_t>(i), 6, 0.5});
    m.pose_b = fcl_style_pose(c);
    const Vec3 before = m.pose_b.translation;
    bisect_to_contact(m, c);
    if (m.pose_b.translation == before) continue;
    ++bisected;
    const ExactVerdict v = exact::judge_meshes(m);
    ASSERT_TRUE(v.decided);
    // The nearest pair is within 2^-40 of the scale: at contact up to the translation's ULPs.
    EXPECT_LT(std::fabs(v.margin), 0x1p-40) << v.margin;
  }
  EXPECT_GT(bisected, 15);
}

}  // namespace
}  // namespace cc::harness
