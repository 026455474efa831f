// The Bullet adapters: plain cases, touching, the ranges btRayAabb is asked of, the two ways its
// callers' stand-in for 1/0 (BT_LARGE_FLOAT, 1e30) makes btRayAabb2 wrong, spheres whose
// difference's square underflows, boxes turned and mirrored.
#include "oracle/bullet/bullet_oracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "collide/moving_box.h"
#include "harness/model/mesh_query.h"

namespace cc::bullet_oracle {
namespace {

using harness::Opinion;

const Aabb kUnit{{0, 0, 0}, {1, 1, 1}};

// Each party's opinion by name.
std::map<std::string, Opinion> ask(const harness::Input& input) {
  std::map<std::string, Opinion> out;
  for (Opinion& o : BulletSecondOpinion().opinions(input)) out[o.party] = o;
  return out;
}

bool hit(const Opinion& o) {
  EXPECT_EQ(o.status, Opinion::Status::answered) << o.party << ": " << o.detail;
  return o.answer.hit;
}

TEST(BulletSecondOpinion, BoxesOverlapWhenTheyTouch) {
  EXPECT_TRUE(hit(ask(harness::AabbAabbInput{kUnit, {{1, 0, 0}, {2, 1, 1}}}).at("bullet.TestAabbAgainstAabb2")));
  EXPECT_FALSE(hit(ask(harness::AabbAabbInput{kUnit, {{std::nextafter(1.0, 2.0), 0, 0}, {2, 1, 1}}})
                       .at("bullet.TestAabbAgainstAabb2")));
}

TEST(BulletSecondOpinion, RaysThroughAndBesideABox) {
  for (const auto& [name, o] : ask(harness::RayAabbInput{{{-1, 0.5, 0.5}, {1, 0, 0}, 0, 3}, kUnit})) EXPECT_TRUE(hit(o)) << name;
  for (const auto& [name, o] : ask(harness::RayAabbInput{{{-1, 2.5, 0.5}, {1, 0, 0}, 0, 3}, kUnit})) EXPECT_FALSE(hit(o)) << name;
}

TEST(BulletSecondOpinion, TheSlabTestsRangeIsOpenTheSegmentTestsClosed) {
  // The segment from x = -1 ending on the face x = 0: touching at t = tmax = 1.
  const auto opinions = ask(harness::RayAabbInput{{{-1, 0.5, 0.5}, {1, 0, 0}, 0, 1}, kUnit});
  EXPECT_FALSE(hit(opinions.at("bullet.btRayAabb2")));
  EXPECT_TRUE(hit(opinions.at("bullet.btRayAabb")));
}

TEST(BulletSecondOpinion, TheSegmentTestIsAskedOfShortSegmentsOnly) {
  const auto infinite = ask(harness::RayAabbInput{{{-1, 0.5, 0.5}, {1, 0, 0}, 0, INFINITY}, kUnit});
  EXPECT_EQ(infinite.at("bullet.btRayAabb").status, Opinion::Status::not_applicable);
  EXPECT_TRUE(hit(infinite.at("bullet.btRayAabb2")));
  const auto far = ask(harness::RayAabbInput{{{-1, 0.5, 0.5}, {1, 0, 0}, 0, 100}, kUnit});  // ends 99 scales away
  EXPECT_EQ(far.at("bullet.btRayAabb").status, Opinion::Status::not_applicable);
}

TEST(BulletSecondOpinion, TheStandInForOneOverZeroCapsHitsAt1e30AndMovesPoints) {
  // Parallel to x (inside its slab), entering the box at t = 3.57e165: Bullet misses it.
  EXPECT_FALSE(hit(ask(harness::RayAabbInput{{{1, -62, -32}, {0, 1.7365302730352168e-164, 8.682651365176084e-165}, 0, INFINITY},
                                              {{0, 0, -1}, {2, 1, 0}}})
                       .at("bullet.btRayAabb2")));
  // A point below the box, with tmax = inf: Bullet's point moves at speed 1e-30 and reaches it.
  EXPECT_TRUE(hit(ask(harness::RayAabbInput{{{0, 0, 0}, {0, 0, 0}, 0, INFINITY}, {{0, 0, 1}, {1, 1, 1}}})
                      .at("bullet.btRayAabb2")));
}

TEST(BulletSecondOpinion, SpheresTouchingMeetAndASquareThatUnderflowsMeetsTooSoon) {
  const auto says = [](const harness::SphereSphereInput& in) { return hit(ask(in).at("bullet.btSphereSphereCollisionAlgorithm")); };
  EXPECT_TRUE(says({{{0, 0, 0}, 1}, {{2, 0, 0}, 1}}));  // touching
  EXPECT_FALSE(says({{{0, 0, 0}, 1}, {{std::nextafter(2.0, 3.0), 0, 0}, 1}}));
  // Apart by 1e-170 with radii 1e-171: the difference's square underflows to 0, a contact.
  EXPECT_TRUE(says({{{0, 0, 0}, 1e-171}, {{1e-170, 0, 0}, 1e-171}}));
}

TEST(BulletSecondOpinion, BoxesFaceToFaceAndTurned) {
  const auto says = [](const harness::ObbObbInput& in) { return hit(ask(in).at("bullet.btBoxBoxDetector")); };
  const Obb a{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
  EXPECT_TRUE(says({a, {{2, 0, 0}, {1, 1, 1}, Mat3::identity()}}));  // sharing the face x = 1
  EXPECT_TRUE(says({a, {{1.5, 0.5, 0}, {1, 1, 1}, Mat3::identity()}}));
  EXPECT_FALSE(says({a, {{2.01, 0, 0}, {1, 1, 1}, Mat3::identity()}}));
  const double c = std::sqrt(0.5);
  const Mat3 turned = Mat3::from_columns({c, c, 0}, {-c, c, 0}, {0, 0, 1});  // 45 degrees about z
  EXPECT_TRUE(says({a, {{2.3, 0, 0}, {1, 1, 1}, turned}}));   // its corner reaches x = 2.3 - sqrt 2
  EXPECT_FALSE(says({a, {{2.5, 0, 0}, {1, 1, 1}, turned}}));  // x = 2.5 - sqrt 2 > 1
  const Mat3 mirror = Mat3::from_columns({0, 1, 0}, {1, 0, 0}, {0, 0, 1});
  EXPECT_TRUE(says({a, {{1.5, 0.5, 0}, {1, 1, 1}, mirror}}));  // a mirror-image frame, the same box
}

// Two parallel right triangles, face 0 in the plane z = 2 and face 1 in z = 1, legs x, y in [0, 4].
harness::RayMeshInput ray_on_two_faces(const Ray& ray) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 2}, {4, 0, 2}, {0, 4, 2}, {0, 0, 1}, {4, 0, 1}, {0, 4, 1}};
  mesh.faces = {{0, 1, 2}, {3, 4, 5}};
  return {harness::triangles_mesh(mesh), ray, {}};
}

TEST(BulletSecondOpinion, ARaycastNamesTheNearestFaceAndMissesAtAPlanesEnd) {
  const auto says = [](const Ray& ray) { return ask(ray_on_two_faces(ray)).at("bullet.btBvhTriangleMeshShape::performRaycast"); };
  const Opinion up = says({{1, 1, 0}, {0, 0, 3}, 0, 1});  // through z = 1 at t = 1/3, then z = 2
  ASSERT_TRUE(hit(up));
  EXPECT_EQ(up.answer.pairs, (std::vector<harness::FacePair>{{1, 0}}));
  const Opinion down = says({{1, 1, 3}, {0, 0, -3}, 0, 1});
  ASSERT_TRUE(hit(down));
  EXPECT_EQ(down.answer.pairs, (std::vector<harness::FacePair>{{0, 0}}));
  EXPECT_FALSE(hit(says({{1, 1, 0}, {0, 0, 1}, 0, 1})));  // ends on face 1's plane: Bullet's miss
  EXPECT_FALSE(hit(says({{5, 5, 0}, {0, 0, 3}, 0, 1})));  // beside both faces
  EXPECT_EQ(says({{1, 1, 0}, {0, 0, 1}, 0, INFINITY}).status, Opinion::Status::not_applicable);
}

TEST(BulletSecondOpinion, BothBroadphasesFollowBoxesAddedMovedAndRemoved) {
  const Aabb unit{{0, 0, 0}, {1, 1, 1}};
  harness::BroadphaseInput in;
  in.frames = {{unit, Aabb{{2, 0, 0}, {3, 1, 1}}},                            // apart
               {unit, Aabb{{1, 0, 0}, {2, 1, 1}}, Aabb{{0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}}},  // touching; a third inside
               {std::nullopt, Aabb{{1, 0, 0}, {2, 1, 1}}, Aabb{{0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}}}};  // the first gone
  const std::vector<std::vector<harness::FacePair>> expected = {{}, {{0, 1}, {0, 2}}, {}};
  for (const char* party : {"bullet.btAxisSweep3", "bullet.btDbvtBroadphase"}) {
    const Opinion o = ask(in).at(party);
    ASSERT_TRUE(hit(o)) << party;
    EXPECT_EQ(o.answer.frames, expected) << party;
  }
}

TEST(BulletSecondOpinion, GjkOnATriangleAndABox) {
  const auto aabb = [](const harness::TriAabbInput& in) { return hit(ask(in).at("bullet.btGjkPairDetector")); };
  const auto obb = [](const harness::TriObbInput& in) { return hit(ask(in).at("bullet.btGjkPairDetector")); };
  const Triangle through{{Vec3{-1, 0.5, 0.5}, Vec3{2, 0.5, 0.5}, Vec3{0.5, 3, 0.5}}};
  EXPECT_TRUE(aabb({through, kUnit}));
  EXPECT_FALSE(aabb({{{Vec3{3, 3, 3}, Vec3{4, 3, 3}, Vec3{3, 4, 3}}}, kUnit}));
  const double c = std::sqrt(0.5);
  const Obb turned{{0, 0, 0}, {1, 1, 1}, Mat3::from_columns({c, c, 0}, {-c, c, 0}, {0, 0, 1})};
  EXPECT_TRUE(obb({{{Vec3{1.3, 0, -1}, Vec3{1.3, 0, 1}, Vec3{3, 0, 0}}}, turned}));   // the corner reaches x = sqrt 2
  EXPECT_FALSE(obb({{{Vec3{1.5, 0, -1}, Vec3{1.5, 0, 1}, Vec3{3, 0, 0}}}, turned}));
}

TEST(BulletSecondOpinion, ACastFindsBoxesMeetingDuringTheStep) {
  const auto says = [](const harness::MovingObbInput& in) { return hit(ask(in).at("bullet.btGjkConvexCast")); };
  const Obb unit{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
  const auto moving = [](const Obb& box, const Vec3& velocity) { return MovingObb{box, velocity}; };
  EXPECT_TRUE(says({moving(unit, {0, 0, 0}), moving({{4, 0, 0}, {1, 1, 1}, Mat3::identity()}, {-3, 0, 0})}));  // meet at t = 2/3
  EXPECT_FALSE(says({moving(unit, {0, 0, 0}), moving({{4, 0, 0}, {1, 1, 1}, Mat3::identity()}, {-1, 0, 0})}));  // stop 1 short
  EXPECT_FALSE(says({moving(unit, {0, 0, 0}), moving({{0, 3, 0}, {1, 1, 1}, Mat3::identity()}, {5, 0, 0})}));   // pass beside
  EXPECT_TRUE(says({moving(unit, {1, 0, 0}), moving({{0.5, 0, 0}, {1, 1, 1}, Mat3::identity()}, {1, 0, 0})}));  // overlapping at the start
}

TEST(BulletSecondOpinion, GImpactFindsTheFacesOfTwoMeshesThatCross) {
  Mesh a, b;
  a.vertices = {{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}, {10, 10, 10}, {11, 10, 10}, {10, 11, 10}};  // face 1 far away
  a.faces = {{0, 1, 2}, {3, 4, 5}};
  b.vertices = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}};  // through face 0 of a
  b.faces = {{0, 1, 2}};
  harness::MeshPair pair{harness::triangles_mesh(a), harness::triangles_mesh(b), {}, {}, {}};
  const Opinion crossing = ask(harness::MeshMeshInput{pair}).at("bullet.btGImpactCollisionAlgorithm");
  ASSERT_TRUE(hit(crossing));
  EXPECT_EQ(crossing.answer.pairs, (std::vector<harness::FacePair>{{0, 0}}));
  pair.pose_b.translation = {0, 0, 5};  // lifted clear
  EXPECT_FALSE(hit(ask(harness::MeshMeshInput{pair}).at("bullet.btGImpactCollisionAlgorithm")));
  EXPECT_FALSE(hit(ask(harness::MeshMeshFirstInput{pair}).at("bullet.btGImpactCollisionAlgorithm")));
}

TEST(BulletSecondOpinion, PartiesMatchTheOpinionsOfEveryKind) {
  const BulletSecondOpinion bullet;
  for (harness::QueryKind kind : harness::kAllQueryKinds) {
    const auto opinions = bullet.opinions(harness::with_kind(kind, []<class In>() { return harness::Input(In{}); }));
    const auto parties = bullet.parties(kind);
    ASSERT_EQ(opinions.size(), parties.size()) << name(kind);
    for (std::size_t i = 0; i < parties.size(); ++i) EXPECT_EQ(opinions[i].party, parties[i].party);
  }
  EXPECT_EQ(bullet.parties(harness::QueryKind::ray_aabb).size(), 2u);
  EXPECT_EQ(bullet.parties(harness::QueryKind::aabb_aabb).size(), 1u);
  EXPECT_EQ(bullet.parties(harness::QueryKind::sphere_sphere).size(), 1u);
  EXPECT_EQ(bullet.parties(harness::QueryKind::obb_obb).size(), 1u);
  EXPECT_EQ(bullet.parties(harness::QueryKind::ray_mesh).size(), 1u);
  EXPECT_EQ(bullet.parties(harness::QueryKind::broadphase).size(), 2u);
  EXPECT_EQ(bullet.parties(harness::QueryKind::tri_aabb).size(), 1u);
  EXPECT_EQ(bullet.parties(harness::QueryKind::tri_obb).size(), 1u);
  EXPECT_EQ(bullet.parties(harness::QueryKind::moving_obb).size(), 1u);
  EXPECT_EQ(bullet.parties(harness::QueryKind::mesh_mesh).size(), 1u);
  EXPECT_EQ(bullet.parties(harness::QueryKind::mesh_mesh_first).size(), 1u);
}

TEST(BulletSecondOpinion, ItsVersionIsTheHeadersOne) { EXPECT_EQ(bullet_version(), "3.24"); }

}  // namespace
}  // namespace cc::bullet_oracle
