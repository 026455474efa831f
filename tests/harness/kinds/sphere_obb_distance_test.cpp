// The sphere_obb_distance kind's unit: its answer (the signed distance, the witnesses and their
// bounds), its exact verdict with the centre outside, inside and on the boundary, how a witness
// inside the box rather than on its boundary is judged, and its domain.
#include "harness/kinds/sphere_obb_distance.h"

#include <gtest/gtest.h>

#include "harness/judging/classify.h"
#include "harness/model/library.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

using Kind = Query<SphereObbDistanceInput>;

const Obb kUnitBox{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
// A ball of radius 1: beyond the corner (1, 1, 1) by (2, 2, 1) (3 from it: 2 apart); centred 0.5
// under the top face (-1.5: the depth 0.5 plus the radius); centred on the top face (-1).
const SphereObbDistanceInput kBeyondACorner{{{3, 3, 2}, 1}, kUnitBox};
const SphereObbDistanceInput kInside{{{0, 0, 0.5}, 1}, kUnitBox};
const SphereObbDistanceInput kOnAFace{{{0.25, 0, 1}, 1}, kUnitBox};

TEST(SphereObbDistanceKind, TheAnswerIsTheSignedDistanceTheWitnessesAndTheirBounds) {
  const Answer a = Kind::ask(kBeyondACorner);
  EXPECT_FALSE(a.hit);
  ASSERT_EQ(a.params.size(), 9u);
  EXPECT_NEAR(a.params[0], 2, 1e-14);
  EXPECT_EQ((Vec3{a.params[4], a.params[5], a.params[6]}), (Vec3{1, 1, 1}));  // the box's corner
  const Answer inside = Kind::ask(kInside);
  EXPECT_TRUE(inside.hit);
  EXPECT_NEAR(inside.params[0], -1.5, 1e-14);
  EXPECT_EQ(ask_library(Input{kInside}), inside);
}

TEST(SphereObbDistanceKind, TheExactVerdictIsSignedAndItsWitnessesAreOnTheBoundaries) {
  const exact::ExactRationalReference exact;
  const std::pair<const SphereObbDistanceInput*, double> cases[] = {{&kBeyondACorner, 2}, {&kInside, -1.5}, {&kOnAFace, -1}};
  for (const auto& [in, distance] : cases) {
    const ExactVerdict v = exact.judge(Input{*in});
    ASSERT_EQ(v.contract, Contract::in);
    EXPECT_EQ(v.answer.hit, distance < 0);
    EXPECT_EQ(v.answer.params, std::vector<double>{distance});
    EXPECT_EQ(classify(QueryKind::sphere_obb_distance, Kind::ask(*in), v, {}).cls, CaseClass::agree) << distance;
  }
  // The box's witness of the ball inside must lie on the box's boundary: the ball's centre, inside
  // the box, is 0.5 from it, a thousand times the bound.
  const ExactVerdict v = exact.judge(Input{kInside});
  Answer inside = Kind::ask(kInside);
  inside.params[4] = 0, inside.params[5] = 0, inside.params[6] = 0.5;
  const Verdict w = classify(QueryKind::sphere_obb_distance, inside, v, {});
  EXPECT_EQ(w.cls, CaseClass::impl_bug);
  EXPECT_NE(w.parties[0].why.find("on_b lies"), std::string::npos);
}

TEST(SphereObbDistanceKind, TheDomainReachesFrom0To2To500) {
  const exact::ExactRationalReference exact;
  const auto scaled = [](double s) {
    SphereObbDistanceInput in = kBeyondACorner;
    in.ball.center = s * in.ball.center, in.ball.radius *= s, in.box.half = s * in.box.half;
    return Input{in};
  };
  EXPECT_EQ(exact.judge(scaled(0x1p-1000)).contract, Contract::in);
  EXPECT_EQ(exact.judge(scaled(0x1p400)).contract, Contract::in);
  EXPECT_EQ(exact.judge(scaled(0x1p600)).contract, Contract::unspecified);
  SphereObbDistanceInput skewed = kBeyondACorner;
  skewed.box.axes.col[0].y = 0x1p-20;  // far beyond the orthonormality tolerance
  EXPECT_EQ(exact.judge(Input{skewed}).contract, Contract::unspecified);
  for (double s : {0x1p-1000, 0x1p400}) {
    EXPECT_EQ(classify(QueryKind::sphere_obb_distance, ask_library(scaled(s)), exact.judge(scaled(s)), {}).cls, CaseClass::agree);
  }
}

}  // namespace
}  // namespace cc::harness
