// The mesh_mesh_distance kind's unit: its answer (the distance, the witnesses and their bounds)
// on meshes apart, touching and crossing; its exact verdict and how a wrong distance or a witness
// off its mesh is judged; FCL's parties; the generator's hierarchies; and the domain.
#include "harness/kinds/mesh_mesh_distance.h"

#include <gtest/gtest.h>

#include "harness/generation/choices.h"
#include "harness/generation/generate.h"
#include "harness/generation/values.h"
#include "harness/judging/classify.h"
#include "harness/model/library.h"
#include "harness/model/mesh_query.h"
#include "oracle/exact/exact_reference.h"
#include "oracle/fcl/fcl_oracle.h"

namespace cc::harness {
namespace {

using Kind = Query<MeshMeshDistanceInput>;

// Mesh a: two triangles in the plane z = 0; mesh b: one triangle standing `lift` above it.
MeshMeshDistanceInput floor_and_post(double lift, BvType bv = BvType::obb) {
  Mesh floor{{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {10, 10, 0}, {12, 10, 0}, {10, 12, 0}}, {{0, 1, 2}, {3, 4, 5}}};
  Mesh post{{{0.5, 0.5, lift}, {0.5, 0.5, 1 + lift}, {0.75, 0.5, 1 + lift}}, {{0, 1, 2}}};
  MeshMeshDistanceInput in;
  in.meshes.a = triangles_mesh(std::move(floor));
  in.meshes.b = triangles_mesh(std::move(post));
  in.meshes.library.bv = bv;
  return in;
}

TEST(MeshMeshDistanceKind, TheAnswerIsTheDistanceTheWitnessesAndTheirBounds) {
  for (BvType bv : {BvType::obb, BvType::sphere, BvType::aabb}) {  // Aabb cases walk Obb trees
    const Answer apart = Kind::ask(floor_and_post(0.25, bv));
    EXPECT_FALSE(apart.hit);
    ASSERT_EQ(apart.params.size(), 9u);
    EXPECT_NEAR(apart.params[0], 0.25, apart.params[7]);
    EXPECT_EQ(apart.params[3], 0.0);     // on_a on the floor
    EXPECT_EQ(apart.params[6], 0.25);    // on_b the post's foot
    EXPECT_GT(apart.params[7], 0);
    EXPECT_LT(apart.params[7], 0x1p-40);
    const Answer touching = Kind::ask(floor_and_post(0, bv));
    EXPECT_TRUE(touching.hit);
    EXPECT_EQ(touching.params[0], 0);
    EXPECT_TRUE(Kind::ask(floor_and_post(-0.5, bv)).hit);  // crossing
  }
  EXPECT_EQ(ask_library(Input{floor_and_post(0.25)}), Kind::ask(floor_and_post(0.25)));
}

TEST(MeshMeshDistanceKind, TheExactVerdictChecksTheDistanceAndTheWitnesses) {
  const exact::ExactRationalReference exact;
  const MeshMeshDistanceInput in = floor_and_post(0.25);
  const ExactVerdict v = exact.judge(Input{in});
  ASSERT_EQ(v.contract, Contract::in);
  EXPECT_FALSE(v.answer.hit);
  EXPECT_EQ(v.answer.params, std::vector<double>{0.25});
  EXPECT_LT(v.margin, 0);
  const Answer right = Kind::ask(in);
  EXPECT_EQ(classify(QueryKind::mesh_mesh_distance, right, v, {}).cls, CaseClass::agree);
  Answer farther = right;
  farther.params[0] = 0.5;
  const Verdict w = classify(QueryKind::mesh_mesh_distance, farther, v, {});
  EXPECT_EQ(w.cls, CaseClass::impl_bug);
  EXPECT_NE(w.parties[0].why.find("distance"), std::string::npos);
  // A witness in the plane and the bounding box of a's first face, but off it (x + y = 3 > 2).
  Answer off = right;
  off.params[1] = 1.5, off.params[2] = 1.5, off.params[3] = 0;
  EXPECT_NE(classify(QueryKind::mesh_mesh_distance, off, v, {}).parties[0].why.find("on_a lies"), std::string::npos);
  const ExactVerdict touching = exact.judge(Input{floor_and_post(0)});
  EXPECT_TRUE(touching.answer.hit);
  EXPECT_EQ(touching.margin, 0);
}

TEST(MeshMeshDistanceKind, FclsPartiesAgreeOnMeshesApart) {
  const exact::ExactRationalReference exact;
  const MeshMeshDistanceInput in = floor_and_post(0.25);
  const auto opinions = fcl_oracle::FclSecondOpinion().opinions(Input{in});
  ASSERT_EQ(opinions.size(), 2u);
  for (const Opinion& o : opinions) {
    ASSERT_EQ(o.status, Opinion::Status::answered) << o.party;
    ASSERT_EQ(o.answer.params.size(), 7u) << o.party;
    EXPECT_NEAR(o.answer.params[0], 0.25, 1e-15) << o.party;
  }
  EXPECT_EQ(classify(QueryKind::mesh_mesh_distance, Kind::ask(in), exact.judge(Input{in}), opinions).cls, CaseClass::agree);
}

TEST(MeshMeshDistanceKind, TheGeneratorDrawsObbOrSphereTrees) {
  int obb = 0, sphere = 0;
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    RandomChoices c(seed);
    ValueSource v(c, {});
    const MeshMeshDistanceInput in = Kind::generate(v, {});
    const BvType bv = in.meshes.library.bv;
    ASSERT_TRUE(bv == BvType::obb || bv == BvType::sphere);
    (bv == BvType::obb ? obb : sphere) += 1;
  }
  EXPECT_GT(obb, 0);
  EXPECT_GT(sphere, 0);
}

TEST(MeshMeshDistanceKind, PosesOutsideTheDomain) {
  const exact::ExactRationalReference exact;
  MeshMeshDistanceInput mirror = floor_and_post(0.25);
  mirror.meshes.pose_b.rotation.col[2] = -1.0 * mirror.meshes.pose_b.rotation.col[2];
  EXPECT_NE(exact.judge(Input{mirror}).contract, Contract::in);
  MeshMeshDistanceInput far = floor_and_post(0.25);
  far.meshes.pose_b.translation = {0x1p400, 0, 0};
  EXPECT_NE(exact.judge(Input{far}).contract, Contract::in);
}

}  // namespace
}  // namespace cc::harness
