// The FCL and libccd adapters: that they answer plain cases, say "not applicable" where they
// have no answer, and survive a call that never returns.
#include "oracle/fcl/fcl_oracle.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace cc::fcl_oracle {
namespace {

using harness::Opinion;

const Aabb kUnit{{0, 0, 0}, {1, 1, 1}};
const Triangle kTriangle{{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}};

std::vector<Opinion> ask(const harness::Input& input) { return FclSecondOpinion().opinions(input); }

void expect_answers(const harness::Input& input, bool hit) {
  for (const Opinion& o : ask(input)) {
    EXPECT_EQ(o.status, Opinion::Status::answered) << o.party << ": " << o.detail;
    EXPECT_EQ(o.answer.hit, hit) << o.party;
  }
}

TEST(FclSecondOpinion, AnswersPlainCases) {
  expect_answers(harness::AabbAabbInput{kUnit, {{0.5, 0.5, 0.5}, {2, 2, 2}}}, true);
  expect_answers(harness::AabbAabbInput{kUnit, {{3, 3, 3}, {4, 4, 4}}}, false);
  expect_answers(harness::SphereSphereInput{{{0, 0, 0}, 1}, {{1.5, 0, 0}, 1}}, true);
  expect_answers(harness::SphereSphereInput{{{0, 0, 0}, 1}, {{3, 0, 0}, 1}}, false);
  const Obb a{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
  expect_answers(harness::ObbObbInput{a, {{1.5, 0, 0}, {1, 1, 1}, Mat3::identity()}}, true);
  expect_answers(harness::ObbObbInput{a, {{3, 0, 0}, {1, 1, 1}, Mat3::identity()}}, false);
  expect_answers(harness::KdopKdopInput{18, {{0, 0, 0}, {1, 1, 1}}, {{0.5, 0.5, 0.5}}}, true);
  expect_answers(harness::TriTriInput{kTriangle, {{Vec3{0.25, 0.25, -1}, Vec3{0.25, 0.25, 1}, Vec3{0.3, 0.2, 1}}}}, true);
  expect_answers(harness::TriAabbInput{kTriangle, {{0.1, 0.1, -1}, {0.2, 0.2, 1}}}, true);
  expect_answers(harness::TriObbInput{kTriangle, {{3, 3, 3}, {1, 1, 1}, Mat3::identity()}}, false);
  expect_answers(harness::RayAabbInput{{{-1, 0.5, 0.5}, {1, 0, 0}, 0, 3}, kUnit}, true);
  expect_answers(harness::RayAabbInput{{{-1, 2.5, 0.5}, {1, 0, 0}, 0, 3}, kUnit}, false);
}

TEST(FclSecondOpinion, IsNotApplicableWhereFclHasNoSuchQuery) {
  for (const Opinion& o : ask(harness::RayAabbInput{{{-1, 0.5, 0.5}, {1, 0, 0}, 0, INFINITY}, kUnit})) {
    EXPECT_EQ(o.status, Opinion::Status::not_applicable) << o.party;
  }
  for (const Opinion& o : ask(harness::RayAabbInput{{{-1, 0.5, 0.5}, {1, 0, 0}, 2, 1}, kUnit})) {
    EXPECT_EQ(o.status, Opinion::Status::not_applicable) << o.party;  // tmin > tmax: empty
  }
  EXPECT_EQ(ask(harness::KdopKdopInput{14, {{0, 0, 0}}, {{0, 0, 0}}})[0].status, Opinion::Status::not_applicable);
}

TEST(FclSecondOpinion, PartiesMatchTheOpinions) {
  const FclSecondOpinion fcl;
  const auto opinions = fcl.opinions(harness::ObbObbInput{});
  const auto parties = fcl.parties(harness::QueryKind::obb_obb);
  ASSERT_EQ(opinions.size(), parties.size());
  for (std::size_t i = 0; i < parties.size(); ++i) EXPECT_EQ(opinions[i].party, parties[i].party);
}

TEST(FclSecondOpinion, ACallThatNeverReturnsIsAFailedOpinion) {
  // libccd's MPR loops forever on this long, thin triangle against a small box (found by the
  // first campaign). The adapter gives up after its time limit.
  harness::TriObbInput in;
  in.tri = {{Vec3{4.478030034286684e+38, 4.457931857581931e+38, 1.2055763490749499e+39},
             Vec3{-32.399955162504774, -26.84344970919607, -0.31331715383751507},
             Vec3{-32.401356381084, -26.848456768097172, -0.3511529302363027}}};
  in.box = {{-30.092816567548695, -30.092816567548695, 0.03125},
            {1, 4, 0.042765799237559375},
            Mat3::from_columns({0.7477182773146395, 0.48252822015093966, -0.45616213622745394},
                               {0.5767846487390197, -0.8123417145881564, 0.08614178845937877},
                               {-0.32899368800728324, -0.32751710718364163, -0.885717617389101})};
  const auto start = std::chrono::steady_clock::now();
  const auto opinions = ask(in);
  ASSERT_EQ(opinions.size(), 1u);
  EXPECT_EQ(opinions[0].status, Opinion::Status::timed_out);  // never taken as an answer
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

}  // namespace
}  // namespace cc::fcl_oracle

namespace cc::fcl_oracle {
namespace {

TEST(FclSecondOpinion, MirrorImageBoxFramesAreHandedToFclAsRotations) {
  // The box with frame columns (0,0,1), (0,-1,0), (-1,0,0) (det = -1) around (-64, 3.5, 0) and a
  // triangle deep inside it: found by the campaign as a "miss" from shapeTriangleIntersect until
  // the adapter made the frame proper (libccd takes rotations as quaternions).
  harness::TriObbInput in;
  in.box = {{-64, 3.5, 2.225073858507201e-308},
            {4.203376770019531, 4.227246846337192, 1.25},
            Mat3::from_columns({0, 0, 1}, {0, -1, 0}, {-1, 0, 0})};
  in.tri = {{Vec3{-62.75, 7.727246846337192, -4.203376770019531}, Vec3{-65.25, 3.5, -4.203376770019531},
             Vec3{-67.5, 0.5, -0.010076055718200376}}};
  const auto opinions = FclSecondOpinion().opinions(in);
  ASSERT_EQ(opinions.size(), 1u);
  EXPECT_TRUE(opinions[0].answer.hit);
}

// On a NaN or an infinite coordinate libccd reads memory it never set, and fresh processes
// answered a stored case (triangle with a vertex at z = -inf) hit and miss: no answer is taken.
TEST(FclSecondOpinion, LibccdIsNotAskedAboutNonFiniteCoordinates) {
  harness::TriAabbInput in;
  in.tri = {{Vec3{-131078.75, 4, 8.05928447842598}, Vec3{-262143.99999999997, 10, -INFINITY},
             Vec3{-131073.41413052662, 4, 10.05928447842598}}};
  in.box = {{-131072, 6, 3}, {-131072, 6, 3.1185689568519592}};
  const auto opinions = ask(in);
  ASSERT_EQ(opinions.size(), 1u);
  EXPECT_EQ(opinions[0].status, Opinion::Status::not_applicable);
  EXPECT_EQ(opinions[0].detail, "a NaN or infinite coordinate, on which libccd reads memory it never set");
  in.tri.v[1].z = NAN;
  EXPECT_EQ(ask(in)[0].status, Opinion::Status::not_applicable);
  in.tri.v[1].z = 10;
  EXPECT_EQ(ask(in)[0].status, Opinion::Status::answered);
}

// SSaP's unregisterObject misses a box in its list by y when another box has moved since the
// lists were sorted; its collide() would then read past the end of its list by x, and crashed in
// one process and answered in another. The adapter reports the fault and never calls collide().
TEST(FclSecondOpinion, SSaPsListsOutOfStepAreAFaultNotARead) {
  const Aabb point{{0, 0, 0}, {0, 0, 0}};
  harness::BroadphaseInput in;
  in.frames = {{std::nullopt, point, point, point}, {std::nullopt, point, Aabb{{0, 1, 0}, {0, 1, 0}}, std::nullopt}};
  const auto opinion_of = [](const std::vector<Opinion>& opinions, const std::string& party) {
    for (const Opinion& o : opinions) {
      if (o.party == party) return o;
    }
    return Opinion{};
  };
  const auto opinions = ask(in);
  const Opinion ssap = opinion_of(opinions, "fcl.SSaPCollisionManager");
  EXPECT_EQ(ssap.status, Opinion::Status::failed);
  EXPECT_EQ(ssap.detail.rfind("frame 1: its lists are out of step (2 objects sorted by x, 3 by y, 2 by z", 0), 0u) << ssap.detail;
  const Opinion naive = opinion_of(opinions, "fcl.NaiveCollisionManager");
  ASSERT_EQ(naive.status, Opinion::Status::answered);
  EXPECT_EQ(naive.answer.frames, (std::vector<std::vector<harness::FacePair>>{{{1, 2}, {1, 3}, {2, 3}}, {}}));
  in.frames[1][3] = point;  // nothing leaves: the lists stay in step
  EXPECT_EQ(opinion_of(ask(in), "fcl.SSaPCollisionManager").status, Opinion::Status::answered);
}

}  // namespace
}  // namespace cc::fcl_oracle
