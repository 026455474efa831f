// The sphere_sphere_distance kind's unit: its answer (the signed distance, the witnesses and their
// bounds), its exact verdict apart and overlapping, how a wrong sign, a witness off its sphere
// (at the centre) or a peer's distance alone are judged, and its domain.
#include "harness/kinds/sphere_sphere_distance.h"

#include <gtest/gtest.h>

#include "harness/judging/classify.h"
#include "harness/model/library.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

using Kind = Query<SphereSphereDistanceInput>;

// Radii 1 and 2, centres 5 apart: 2 apart. Centres 1 apart: overlapping by 2.
const SphereSphereDistanceInput kApart{{{0, 0, 0}, 1}, {{3, 4, 0}, 2}};
const SphereSphereDistanceInput kOverlapping{{{0, 0, 0}, 1}, {{0.6, 0.8, 0}, 2}};

Opinion peer(std::vector<double> params, bool hit = false) {
  Opinion o;
  o.party = "peer";
  o.status = Opinion::Status::answered;
  o.answer = Answer::of(hit);
  o.answer.params = std::move(params);
  o.band = Band{0, BandSides::two_sided, 0x1p-40, "a test's"};
  return o;
}

TEST(SphereSphereDistanceKind, TheAnswerIsTheSignedDistanceTheWitnessesAndTheirBounds) {
  const Answer apart = Kind::ask(kApart);
  EXPECT_FALSE(apart.hit);
  ASSERT_EQ(apart.params.size(), 9u);
  EXPECT_NEAR(apart.params[0], 2, 1e-15);
  EXPECT_GT(apart.params[7], 0);
  EXPECT_LT(apart.params[7], 0x1p-40);
  const Answer overlapping = Kind::ask(kOverlapping);
  EXPECT_TRUE(overlapping.hit);
  EXPECT_NEAR(overlapping.params[0], -2, 1e-15);
  EXPECT_EQ(ask_library(Input{kOverlapping}), overlapping);
}

TEST(SphereSphereDistanceKind, TheExactVerdictChecksTheSignedDistanceAndTheWitnesses) {
  const exact::ExactRationalReference exact;
  for (const SphereSphereDistanceInput* p : {&kApart, &kOverlapping}) {
    const SphereSphereDistanceInput& in = *p;
    const ExactVerdict v = exact.judge(Input{in});
    ASSERT_EQ(v.contract, Contract::in);
    EXPECT_EQ(v.answer.hit, p == &kOverlapping);
    EXPECT_EQ(v.answer.params, std::vector<double>{v.answer.hit ? -2.0 : 2.0});
    EXPECT_EQ(v.margin > 0, v.answer.hit);
    const Answer right = Kind::ask(in);
    EXPECT_EQ(classify(QueryKind::sphere_sphere_distance, right, v, {}).cls, CaseClass::agree);
    Answer sign = right;
    sign.params[0] = -sign.params[0];
    const Verdict w = classify(QueryKind::sphere_sphere_distance, sign, v, {});
    EXPECT_EQ(w.cls, CaseClass::impl_bug);
    EXPECT_NE(w.parties[0].why.find("distance"), std::string::npos);
    Answer centre = right;
    centre.params[1] = in.a.center.x, centre.params[2] = in.a.center.y, centre.params[3] = in.a.center.z;
    EXPECT_NE(classify(QueryKind::sphere_sphere_distance, centre, v, {}).parties[0].why.find("on_a lies"), std::string::npos);
  }
}

TEST(SphereSphereDistanceKind, APeerMayGiveTheDistanceAlone) {
  const exact::ExactRationalReference exact;
  const ExactVerdict v = exact.judge(Input{kOverlapping});
  const Answer library = Kind::ask(kOverlapping);
  EXPECT_EQ(classify(QueryKind::sphere_sphere_distance, library, v, {peer({-2}, true)}).cls, CaseClass::agree);
  EXPECT_EQ(classify(QueryKind::sphere_sphere_distance, library, v, {peer({-1.5}, true)}).cls, CaseClass::oracle_defect);
  // Its points, where it gives them, are judged: the contact's position twice is 0 apart, not 2.
  EXPECT_EQ(classify(QueryKind::sphere_sphere_distance, library, v, {peer({-2, 0.3, 0.4, 0, 0.3, 0.4, 0}, true)}).cls,
            CaseClass::oracle_defect);
  // Collision with no distance is judged on the hit.
  EXPECT_EQ(classify(QueryKind::sphere_sphere_distance, library, v, {peer({}, true)}).cls, CaseClass::agree);
  EXPECT_EQ(classify(QueryKind::sphere_sphere_distance, library, v, {peer({}, false)}).cls, CaseClass::oracle_defect);
}

TEST(SphereSphereDistanceKind, TheDomainReachesFrom0To2To500) {
  const exact::ExactRationalReference exact;
  const auto scaled = [](double s) {
    SphereSphereDistanceInput in = kApart;
    for (Sphere* b : {&in.a, &in.b}) b->center = s * b->center, b->radius *= s;
    return Input{in};
  };
  EXPECT_EQ(exact.judge(scaled(0x1p-1000)).contract, Contract::in);
  EXPECT_EQ(exact.judge(scaled(0x1p400)).contract, Contract::in);
  EXPECT_EQ(exact.judge(scaled(0x1p600)).contract, Contract::unspecified);
  EXPECT_EQ(exact.judge(Input{SphereSphereDistanceInput{{{0, 0, 0}, -1}, {{1, 0, 0}, 1}}}).contract, Contract::documented);
  for (double s : {0x1p-1000, 0x1p400}) {
    EXPECT_EQ(classify(QueryKind::sphere_sphere_distance, ask_library(scaled(s)), exact.judge(scaled(s)), {}).cls,
              CaseClass::agree);
  }
}

}  // namespace
}  // namespace cc::harness
