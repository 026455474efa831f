// The ODE adapters: plain hits and misses for every party, touching and apart by one ULP where
// the band allows a decision, the rays ODE is not asked, boxes turned and mirrored, triangle
// meshes, both spaces following boxes added, moved and removed.
#include "oracle/ode/ode_oracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

#include "harness/model/mesh_query.h"
#include "harness/model/party.h"
#include "oracle/ode/ode_call.h"
#include "oracle/ode/trimesh.h"

namespace cc::ode_oracle {
namespace {

using harness::Opinion;

const Aabb kUnit{{0, 0, 0}, {1, 1, 1}};

// Each party's opinion by name.
std::map<std::string, Opinion> ask(const harness::Input& input) {
  std::map<std::string, Opinion> out;
  for (Opinion& o : OdeSecondOpinion().opinions(input)) out[o.party] = o;
  return out;
}

bool hit(const Opinion& o) {
  EXPECT_EQ(o.status, Opinion::Status::answered) << o.party << ": " << o.detail;
  return o.answer.hit;
}

TEST(OdeSecondOpinion, AxisAlignedBoxesTouchingAndApartByOneUlp) {
  const auto says = [](const harness::AabbAabbInput& in) { return hit(ask(in).at("ode.dCollide(dBox,dBox)")); };
  EXPECT_TRUE(says({kUnit, {{0.5, 0.5, 0.5}, {2, 2, 2}}}));
  EXPECT_TRUE(says({kUnit, {{1, 0, 0}, {2, 1, 1}}}));  // sharing the face x = 1
  EXPECT_FALSE(says({kUnit, {{std::nextafter(1.0, 2.0), 0, 0}, {2, 1, 1}}}));
  EXPECT_FALSE(says({kUnit, {{3, 3, 3}, {4, 4, 4}}}));
  EXPECT_EQ(ask(harness::AabbAabbInput{kUnit, {{2, 0, 0}, {1, 1, 1}}}).at("ode.dCollide(dBox,dBox)").status,
            Opinion::Status::not_applicable);  // inverted
}

TEST(OdeSecondOpinion, OrientedBoxesFaceToFaceTurnedAndMirrored) {
  const Obb a{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
  const double c = std::sqrt(0.5);
  const Mat3 turned = Mat3::from_columns({c, c, 0}, {-c, c, 0}, {0, 0, 1});  // 45 degrees about z
  const Mat3 mirror = Mat3::from_columns({0, 1, 0}, {1, 0, 0}, {0, 0, 1});
  for (const char* party : {"ode.dBoxTouchesBox", "ode.dCollide(dBox,dBox)"}) {
    const auto says = [party](const harness::ObbObbInput& in) { return hit(ask(in).at(party)); };
    EXPECT_TRUE(says({a, {{2, 0, 0}, {1, 1, 1}, Mat3::identity()}})) << party;  // sharing the face x = 1
    EXPECT_FALSE(says({a, {{std::nextafter(2.0, 3.0), 0, 0}, {1, 1, 1}, Mat3::identity()}})) << party;
    EXPECT_TRUE(says({a, {{1.5, 0.5, 0}, {1, 1, 1}, Mat3::identity()}})) << party;
    EXPECT_TRUE(says({a, {{2.3, 0, 0}, {1, 1, 1}, turned}})) << party;   // its corner reaches x = 2.3 - sqrt 2
    EXPECT_FALSE(says({a, {{2.5, 0, 0}, {1, 1, 1}, turned}})) << party;  // x = 2.5 - sqrt 2 > 1
    EXPECT_TRUE(says({a, {{1.5, 0.5, 0}, {1, 1, 1}, mirror}})) << party;
    EXPECT_EQ(ask(harness::ObbObbInput{a, {{0, 0, 0}, {-1, 1, 1}, Mat3::identity()}}).at(party).status,
              Opinion::Status::not_applicable);
  }
}

TEST(OdeSecondOpinion, SpheresTouchingAndApartByOneUlp) {
  const auto says = [](const harness::SphereSphereInput& in) {
    return hit(ask(in).at("ode.dCollide(dSphere,dSphere)"));
  };
  EXPECT_TRUE(says({{{0, 0, 0}, 1}, {{1, 1, 0}, 1}}));
  EXPECT_TRUE(says({{{0, 0, 0}, 1}, {{2, 0, 0}, 1}}));  // touching
  EXPECT_FALSE(says({{{0, 0, 0}, 1}, {{std::nextafter(2.0, 3.0), 0, 0}, 1}}));
  EXPECT_FALSE(says({{{0, 0, 0}, 1}, {{5, 0, 0}, 1}}));
  for (const Vec3& apart : {Vec3{0, 2.5, 0}, Vec3{0, 0, 2.5}, Vec3{-1.5, 0, -1.5}}) {  // every coordinate counts
    EXPECT_FALSE(says({{{0, 0, 0}, 1}, {apart, 1}})) << apart.x << " " << apart.y << " " << apart.z;
  }
  EXPECT_TRUE(says({{{0, 0, 0}, 1}, {{0, 0, 2}, 1}}));
}

TEST(OdeSecondOpinion, RaysThroughBesideAndShortOfABox) {
  const auto says = [](const Ray& ray) { return ask(harness::RayAabbInput{ray, kUnit}).at("ode.dCollide(dRay,dBox)"); };
  EXPECT_TRUE(hit(says({{-1, 0.5, 0.5}, {1, 0, 0}, 0, 3})));
  EXPECT_TRUE(hit(says({{-1, 0.5, 0.5}, {2, 0, 0}, 0, INFINITY})));   // infinite: a ray past the box
  EXPECT_TRUE(hit(says({{0.5, 0.5, 0.5}, {0, 1, 0}, 0, INFINITY})));  // from inside: the exit
  EXPECT_FALSE(hit(says({{-1, 2.5, 0.5}, {1, 0, 0}, 0, 3})));
  EXPECT_FALSE(hit(says({{-1, 0.5, 0.5}, {1, 0, 0}, 0, 0.5})));                                   // stops short
  EXPECT_FALSE(hit(says({{-1, 0.5, 0.5}, {-1, 0, 0}, 0, INFINITY})));                             // away from it
  EXPECT_EQ(says({{-1, 0.5, 0.5}, {1, 0, 0}, 0.5, 3}).status, Opinion::Status::not_applicable);   // tmin != 0
  EXPECT_EQ(says({{0.5, 0.5, 0.5}, {1, 0, 0}, 0, 0.1}).status, Opinion::Status::not_applicable);  // inside, finite
  EXPECT_EQ(says({{-1, 0.5, 0.5}, {0, 0, 0}, 0, 1}).status, Opinion::Status::not_applicable);     // zero direction
}

Triangle tri(const Vec3& a, const Vec3& b, const Vec3& c) { return {{a, b, c}}; }

TEST(OdeSecondOpinion, TrianglesCrossingAndApart) {
  const auto says = [](const harness::TriTriInput& in) { return hit(ask(in).at("ode.dCollide(dTriMesh,dTriMesh)")); };
  const Triangle flat = tri({-2, -2, 0}, {2, -2, 0}, {0, 2, 0});
  EXPECT_TRUE(says({flat, tri({0, 0, -1}, {0, 0, 1}, {1, 0, 0})}));   // through it
  EXPECT_FALSE(says({flat, tri({0, 0, 1}, {0, 0, 2}, {1, 0, 1})}));   // above it
  EXPECT_FALSE(says({flat, tri({5, 5, -1}, {5, 5, 1}, {6, 5, 0})}));  // beside it
}

TEST(OdeSecondOpinion, TwoMeshesNameAPairThatCrosses) {
  Mesh a, b;
  a.vertices = {{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}, {10, 10, 10}, {11, 10, 10}, {10, 11, 10}};  // face 1 far away
  a.faces = {{0, 1, 2}, {3, 4, 5}};
  b.vertices = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {20, 0, 0}, {21, 0, 0}, {20, 1, 0}};  // face 0 through face 0 of a
  b.faces = {{3, 4, 5}, {0, 1, 2}};
  harness::MeshPair pair{harness::triangles_mesh(a), harness::triangles_mesh(b), {}, {}, {}};
  const Opinion crossing = ask(harness::MeshMeshFirstInput{pair}).at("ode.dCollide(dTriMesh,dTriMesh)");
  ASSERT_TRUE(hit(crossing));
  EXPECT_EQ(crossing.answer.pairs, (std::vector<harness::FacePair>{{0, 1}}));
  pair.pose_b.translation = {0, 0, 5};  // lifted clear
  EXPECT_FALSE(hit(ask(harness::MeshMeshFirstInput{pair}).at("ode.dCollide(dTriMesh,dTriMesh)")));
}

// Two parallel right triangles, face 0 in the plane z = 2 and face 1 in z = 1, legs x, y in [0, 4].
harness::RayMeshInput ray_on_two_faces(const Ray& ray) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 2}, {4, 0, 2}, {0, 4, 2}, {0, 0, 1}, {4, 0, 1}, {0, 4, 1}};
  mesh.faces = {{0, 1, 2}, {3, 4, 5}};
  return {harness::triangles_mesh(mesh), ray, {}};
}

TEST(OdeSecondOpinion, ARayNamesTheNearestFace) {
  const auto says = [](const Ray& ray) { return ask(ray_on_two_faces(ray)).at("ode.dCollide(dRay,dTriMesh)"); };
  const Opinion up = says({{1, 1, 0}, {0, 0, 3}, 0, 1});  // through z = 1 at t = 1/3, then z = 2
  ASSERT_TRUE(hit(up));
  EXPECT_EQ(up.answer.pairs, (std::vector<harness::FacePair>{{1, 0}}));
  const Opinion down = says({{1, 1, 3}, {0, 0, -1}, 0, INFINITY});
  ASSERT_TRUE(hit(down));
  EXPECT_EQ(down.answer.pairs, (std::vector<harness::FacePair>{{0, 0}}));
  EXPECT_FALSE(hit(says({{1, 1, 0}, {0, 0, 1}, 0, 0.5})));  // stops short of both
  EXPECT_FALSE(hit(says({{5, 5, 0}, {0, 0, 3}, 0, 1})));    // beside both faces
  EXPECT_EQ(says({{1, 1, 0}, {0, 0, 1}, 0.5, 3}).status, Opinion::Status::not_applicable);
}

TEST(OdeSecondOpinion, BothSpacesFollowBoxesAddedMovedAndRemoved) {
  harness::BroadphaseInput in;
  in.frames = {
      {kUnit, Aabb{{2, 0, 0}, {3, 1, 1}}},                                          // apart
      {kUnit, Aabb{{1, 0, 0}, {2, 1, 1}}, Aabb{{0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}}},  // touching; a third inside
      {kUnit, Aabb{{std::nextafter(1.0, 2.0), 0, 0}, {2, 1, 1}}, std::nullopt},     // apart by one ULP; the third gone
      {std::nullopt, Aabb{{1, 0, 0}, {2, 1, 1}}, Aabb{{0, 0, 0}, {0, 0, 0}}}};      // the first gone; a point
  const std::vector<std::vector<harness::FacePair>> expected = {{}, {{0, 1}, {0, 2}}, {}, {}};
  for (const char* party : {"ode.dSweepAndPruneSpace", "ode.dHashSpace"}) {
    const Opinion o = ask(in).at(party);
    ASSERT_TRUE(hit(o)) << party;
    EXPECT_EQ(o.answer.frames, expected) << party;
  }
}

TEST(OdeSecondOpinion, PartiesMatchTheOpinionsOfEveryKind) {
  const OdeSecondOpinion ode;
  for (harness::QueryKind kind : harness::kAllQueryKinds) {
    const auto opinions = ode.opinions(harness::with_kind(kind, []<class In>() { return harness::Input(In{}); }));
    const auto parties = ode.parties(kind);
    ASSERT_EQ(opinions.size(), parties.size()) << name(kind);
    for (std::size_t i = 0; i < parties.size(); ++i) {
      EXPECT_EQ(opinions[i].party, parties[i].party);
      EXPECT_NE(opinions[i].status, Opinion::Status::failed) << opinions[i].party << ": " << opinions[i].detail;
    }
  }
  EXPECT_EQ(ode.parties(harness::QueryKind::ray_aabb).size(), 1u);
  EXPECT_EQ(ode.parties(harness::QueryKind::aabb_aabb).size(), 1u);
  EXPECT_EQ(ode.parties(harness::QueryKind::sphere_sphere).size(), 1u);
  EXPECT_EQ(ode.parties(harness::QueryKind::obb_obb).size(), 2u);
  EXPECT_EQ(ode.parties(harness::QueryKind::tri_tri).size(), 1u);
  EXPECT_EQ(ode.parties(harness::QueryKind::mesh_mesh).size(), 0u);
  EXPECT_EQ(ode.parties(harness::QueryKind::mesh_mesh_first).size(), 1u);
  EXPECT_EQ(ode.parties(harness::QueryKind::ray_mesh).size(), 1u);
  EXPECT_EQ(ode.parties(harness::QueryKind::broadphase).size(), 2u);
}

TEST(OdeSecondOpinion, AnAbortInsideACallIsAFailedOpinion) {
  // ODE's dError and dDebug handlers abort (ODE itself would exit or abort after them): the
  // guard jumps out of the call, and the opinion is failed.
  const Opinion o = ode_call([]() -> Opinion { std::abort(); });
  EXPECT_EQ(o.status, Opinion::Status::failed);
  EXPECT_EQ(ode_call([] { return harness::answered(true); }).status, Opinion::Status::answered);
}

TEST(OdeContacts, EachCallReportsItsOwnContactsAndNoOthers) {
  // contacts() keeps one buffer from call to call: a call finding fewer contacts than the one
  // before it, or none, reports only its own.
  std::vector<dContactGeom> crossing, apart, again;
  const Opinion o = ode_call([&] {
    const Mesh flat{{{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}}, {{0, 1, 2}}};
    const TriMesh a(flat), through(Mesh{{{0, 0, -1}, {0, 0, 1}, {1, 0, 0}}, {{0, 1, 2}}}),
        above(Mesh{{{0, 0, 1}, {0, 0, 2}, {1, 0, 1}}, {{0, 1, 2}}});
    crossing = contacts(a.geom(), through.geom());
    apart = contacts(a.geom(), above.geom());
    again = contacts(a.geom(), through.geom());
    return harness::answered(true);
  });
  ASSERT_EQ(o.status, Opinion::Status::answered) << o.detail;
  ASSERT_FALSE(crossing.empty());
  EXPECT_TRUE(apart.empty());
  ASSERT_EQ(again.size(), crossing.size());
  for (std::size_t i = 0; i < again.size(); ++i) {
    EXPECT_EQ(again[i].depth, crossing[i].depth);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(again[i].pos[k], crossing[i].pos[k]);
  }
}

TEST(OdeSecondOpinion, ItsVersionIsPkgConfigs) { EXPECT_EQ(ode_version(), "0.16.2"); }

}  // namespace
}  // namespace cc::ode_oracle
