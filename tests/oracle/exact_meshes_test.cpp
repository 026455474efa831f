// The exact reference on mesh queries: pair sets and margins on cases worked out by hand, the
// domain, and an undecided verdict instead of a slow one when the scale dwarfs the meshes.
#include "oracle/exact/exact_meshes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>

#include "collide/bvh_collide.h"
#include "harness/formats/mesh_files.h"
#include "harness/model/mesh_query.h"
#include "rotations.h"

namespace cc::exact {
namespace {

QVec3 placed_exactly(const RigidTransform& pose, const Vec3& v) {
  QVec3 out;
  for (int i = 0; i < 3; ++i) out[i] = dot(rational(pose.rotation.row(i)), rational(v)) + rational(pose.translation[i]);
  return out;
}

using test::rotation;

// The filter claims a separation above the threshold only when exact_sat finds one: on triangle
// pairs apart by about the threshold (both sides of it, along face normals and across edges),
// far apart, touching and crossing, degenerate (segments, points), small next to their
// placement, each placed by its own rotation.
TEST(CertainlyApart, ClaimsOnlyWhatTheExactTestFinds) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const double threshold = 0x1p-20;
  int claimed = 0, claimed_near = 0, cases = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const auto point = [&] { return Vec3{uniform(random), uniform(random), uniform(random)}; };
    Triangle a{{point(), point(), point()}}, b{{point(), point(), point()}};
    if (trial % 5 == 1) b.v[2] = b.v[1];                       // a segment
    if (trial % 7 == 2) a.v[1] = a.v[2] = a.v[0];             // a point
    // b moved apart from a along a's normal by about the threshold times a small factor.
    const Vec3 n = cross(a.v[1] - a.v[0], a.v[2] - a.v[0]);
    const double norm = std::sqrt(dot(n, n));
    if (norm > 0 && trial % 3 == 0) {
      const Vec3 unit = (1 / norm) * n;
      const double up = threshold * std::ldexp(1.0, static_cast<int>(trial % 9) - 3);
      // b tilted above a: its lowest vertex `up` above a's plane, the others higher.
      const Vec3 base = (1.0 / 3) * (a.v[0] + a.v[1] + a.v[2]);
      for (int k = 0; k < 3; ++k) {
        const Vec3 q = 0.3 * point();
        b.v[k] = base + (q - dot(q, unit) * unit) + (up + (k ? std::fabs(uniform(random)) : 0.0)) * unit;
      }
      if (trial % 2) {
        for (int k = 0; k < 3; ++k) b.v[k] = a.v[k] + up * unit;  // a's copy lifted by up: flat, not claimed
      }
    }
    const double far = std::ldexp(1.0, static_cast<int>(trial % 11));
    const RigidTransform pa{rotation(uniform(random), uniform(random), uniform(random)), far * point()};
    const RigidTransform pb = trial % 4 ? pa : RigidTransform{rotation(uniform(random), 2, 1), pa.translation};
    ++cases;
    if (!certainly_apart(float_triangle(a, pa), float_triangle(b, pb), threshold)) continue;
    ++claimed;
    const SatResult r = exact_sat(rational_triangle_shape(placed_exactly(pa, a.v[0]), placed_exactly(pa, a.v[1]),
                                                          placed_exactly(pa, a.v[2]), "A"),
                                  rational_triangle_shape(placed_exactly(pb, b.v[0]), placed_exactly(pb, b.v[1]),
                                                          placed_exactly(pb, b.v[2]), "B"));
    ASSERT_FALSE(r.hit) << "trial " << trial;
    ASSERT_GT(-r.margin, threshold * (1 - 0x1p-40)) << "trial " << trial;
    claimed_near += -r.margin < 8 * threshold;
  }
  std::cout << "certainly_apart: " << claimed << " of " << cases << " pairs claimed apart, " << claimed_near
            << " of them within 8 times the threshold" << std::endl;
  EXPECT_GT(claimed, cases / 4);
  EXPECT_GT(claimed_near, cases / 100);
}

using harness::Contract;
using harness::FacePair;
using harness::MeshPair;

// Mesh a: two triangles in the plane z = 0; mesh b: one triangle standing on the plane.
MeshPair floor_and_post(double lift) {
  Mesh floor{{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {10, 10, 0}, {12, 10, 0}, {10, 12, 0}}, {{0, 1, 2}, {3, 4, 5}}};
  Mesh post{{{0.5, 0.5, lift}, {0.5, 0.5, 1 + lift}, {0.6, 0.5, 1 + lift}}, {{0, 1, 2}}};
  MeshPair m;
  m.a = harness::triangles_mesh(std::move(floor));
  m.b = harness::triangles_mesh(std::move(post));
  return m;
}

TEST(JudgeMeshes, AVertexOnAFaceTouches) {
  const harness::ExactVerdict v = judge_meshes(floor_and_post(0));
  EXPECT_EQ(v.contract, Contract::in);
  EXPECT_TRUE(v.decided);
  EXPECT_EQ(v.answer.pairs, (std::vector<FacePair>{{0, 0}}));
  EXPECT_EQ(v.margin, 0);
  EXPECT_EQ(v.margin_of({0, 0}), 0);
}

TEST(JudgeMeshes, ANearPairIsListedWithItsGapAndAFarOneIsNot) {
  const harness::ExactVerdict v = judge_meshes(floor_and_post(0x1p-40));
  EXPECT_FALSE(v.answer.hit);
  EXPECT_TRUE(v.answer.pairs.empty());
  ASSERT_EQ(v.pair_margins.size(), 1u);
  EXPECT_EQ(v.pair_margins[0].pair, (FacePair{0, 0}));
  EXPECT_LT(v.margin, 0);
  EXPECT_GT(v.margin, -0x1p-38);                // apart by 2^-40 of a scale of 12 or so
  EXPECT_EQ(v.margin_of({1, 0}), -kNearMargin);  // the far triangle: not tested
}

TEST(JudgeMeshes, ThePosesPlaceTheMeshesExactly) {
  MeshPair m = floor_and_post(5);  // the post floats 5 above the floor
  m.pose_b.translation = {0, 0, -5};
  EXPECT_EQ(judge_meshes(m).answer.pairs, (std::vector<FacePair>{{0, 0}}));
  // A quarter turn about x takes the floor to the plane y = 0 (x, z >= 0, x + z <= 2): the post
  // moved to y = 0 lies in it (coplanar overlap), moved to y = 0.25 is parallel and apart.
  m.pose_a.rotation = Mat3::from_columns({1, 0, 0}, {0, 0, 1}, {0, -1, 0});
  m.pose_b.translation = {0, -0.5, -5};
  EXPECT_EQ(judge_meshes(m).answer.pairs, (std::vector<FacePair>{{0, 0}}));
  m.pose_b.translation = {0, -0.25, -5};
  EXPECT_FALSE(judge_meshes(m).answer.hit);
}

// The post's foot above the floor's first triangle by `lift`: the distance is the lift, from
// that pair; a pose that turns the post away leaves its nearest vertex 0.5 + lift away, and an
// empty mesh has no pair. Only pairs whose boxes come near are compared in rationals.
TEST(ExactMeshDistance, IsTheLeastOverThePairs) {
  const ExactMeshDistance touching = exact_mesh_distance(floor_and_post(0));
  EXPECT_EQ(touching.squared, 0);
  EXPECT_EQ(touching.faces, (FacePair{0, 0}));
  const ExactMeshDistance lifted = exact_mesh_distance(floor_and_post(0x1p-40));
  EXPECT_EQ(lifted.squared, rational(0x1p-40) * rational(0x1p-40));
  EXPECT_EQ(lifted.faces, (FacePair{0, 0}));
  EXPECT_EQ(lifted.pairs_compared, 1u);  // the far triangle's box is farther than the answer
  MeshPair turned = floor_and_post(0.25);
  turned.pose_b.rotation = Mat3::from_columns({1, 0, 0}, {0, -1, 0}, {0, 0, -1});  // upside down about x
  turned.pose_b.translation = {0, 1, 1.75};  // the foot at (0.5, 0.5, 1.5), the top at z = 0.5
  EXPECT_EQ(exact_mesh_distance(turned).squared, rational(0.25));
  MeshPair empty = floor_and_post(0);
  empty.b = harness::triangles_mesh(Mesh{});
  EXPECT_FALSE(exact_mesh_distance(empty).faces);
}

TEST(JudgeMeshes, AgreesWithBruteForceFarFromContact) {
  MeshPair m;
  m.a = harness::procedural_mesh({ProceduralMesh::Shape::sphere, 1, 8, 1.0});
  m.b = harness::procedural_mesh({ProceduralMesh::Shape::torus, 2, 8, 1.0});
  m.pose_b.translation = {0.75, 0.125, 0.25};
  const harness::ExactVerdict v = judge_meshes(m);
  const auto brute = collide_brute_force(*m.a.mesh, m.pose_a, *m.b.mesh, m.pose_b);
  std::vector<FacePair> expected;
  for (const auto& [fa, fb] : brute) expected.emplace_back(fa, fb);
  ASSERT_FALSE(expected.empty());
  // Pairs nearer than 2^-30 could differ in floating point: there are none here.
  for (const auto& pm : v.pair_margins) ASSERT_GT(std::fabs(pm.margin), 0x1p-30);
  EXPECT_EQ(v.answer.pairs, expected);
}

TEST(JudgeMeshes, PosesOutsideTheDomain) {
  MeshPair m = floor_and_post(0);
  m.pose_b.translation.x = NAN;
  EXPECT_NE(judge_meshes(m).contract, Contract::in);
  m = floor_and_post(0);
  m.pose_a.rotation = Mat3::from_columns({-1, 0, 0}, {0, 1, 0}, {0, 0, 1});  // a mirror
  EXPECT_NE(judge_meshes(m).contract, Contract::in);
  m = floor_and_post(0);
  m.pose_a.rotation = Mat3::from_columns({1, 0, 0}, {0, 1.001, 0}, {0, 0, 1});  // not orthonormal
  EXPECT_NE(judge_meshes(m).contract, Contract::in);
  EXPECT_TRUE(meshes_outside_domain(floor_and_post(0)) == std::nullopt);
}

TEST(JudgeMeshes, TooManyNearPairsAreUndecidedQuickly) {
  const auto folder = std::filesystem::path(CROSSCHECK_SOURCE_DIR) / "corpora" / "meshes";
  MeshPair m;
  m.a.source = m.b.source = harness::MeshRef::Source::file;
  m.a.mesh = harness::load_mesh_file(folder / "env.obj");
  m.b.mesh = harness::load_mesh_file(folder / "rob.obj");
  m.pose_a.translation = m.pose_b.translation = {0, -1.2e83, 0};  // both far out: scale 1e83
  const auto start = std::chrono::steady_clock::now();
  const harness::ExactVerdict v = judge_meshes(m);
  EXPECT_FALSE(v.decided);
  EXPECT_NE(v.note.find("too many"), std::string::npos) << v.note;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5);
}

}  // namespace
}  // namespace cc::exact
