// The obb_obb_distance kind's unit: its answer (the signed distance, the witnesses and their
// bounds), its exact verdict apart, overlapping and touching, how a witness inside a box rather
// than on its boundary is judged, its generator's gaps, and its domain.
#include "harness/kinds/obb_obb_distance.h"

#include <gtest/gtest.h>

#include "harness/generation/generate.h"
#include "harness/judging/classify.h"
#include "harness/model/library.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

using Kind = Query<ObbObbDistanceInput>;

const Obb kUnitBox{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
Obb unit_box_at(const Vec3& c) { return {c, {1, 1, 1}, Mat3::identity()}; }
// Apart by 1.5 along x; overlapping by 0.5 along x (1.8 on y, 2 on z); touching face to face.
const ObbObbDistanceInput kApart{kUnitBox, unit_box_at({3.5, 0.25, -0.5})};
const ObbObbDistanceInput kOverlapping{kUnitBox, unit_box_at({1.5, 0.2, 0})};
const ObbObbDistanceInput kTouching{kUnitBox, unit_box_at({2, 0.5, 0.5})};

TEST(ObbObbDistanceKind, TheAnswerIsTheSignedDistanceTheWitnessesAndTheirBounds) {
  const Answer apart = Kind::ask(kApart);
  EXPECT_FALSE(apart.hit);
  ASSERT_EQ(apart.params.size(), 9u);
  EXPECT_NEAR(apart.params[0], 1.5, 1e-12);
  EXPECT_NEAR(apart.params[1], 1, 1e-15);  // on a's face x = 1
  EXPECT_NEAR(apart.params[4], 2.5, 1e-15);  // on b's face x = 2.5
  const Answer overlapping = Kind::ask(kOverlapping);
  EXPECT_TRUE(overlapping.hit);
  EXPECT_NEAR(overlapping.params[0], -0.5, 1e-12);
  EXPECT_GT(overlapping.params[7], 0);  // the distance's bound
  EXPECT_EQ(ask_library(Input{kOverlapping}), overlapping);
}

TEST(ObbObbDistanceKind, TheExactVerdictIsSignedAndItsWitnessesAreOnTheBoundaries) {
  const exact::ExactRationalReference exact;
  const std::pair<const ObbObbDistanceInput*, double> cases[] = {{&kApart, 1.5}, {&kOverlapping, -0.5}, {&kTouching, 0}};
  for (const auto& [in, distance] : cases) {
    const ExactVerdict v = exact.judge(Input{*in});
    ASSERT_EQ(v.contract, Contract::in);
    EXPECT_EQ(v.answer.hit, distance <= 0);
    EXPECT_EQ(v.answer.params, std::vector<double>{distance});
    EXPECT_EQ(classify(QueryKind::obb_obb_distance, Kind::ask(*in), v, {}).cls, CaseClass::agree) << distance;
  }
  // b's witness of the overlap must lie on b's boundary: b's centre is 1 from it, far beyond the
  // bound.
  const ExactVerdict v = exact.judge(Input{kOverlapping});
  Answer overlapping = Kind::ask(kOverlapping);
  overlapping.params[4] = 1.5, overlapping.params[5] = 0.2, overlapping.params[6] = 0;
  const Verdict w = classify(QueryKind::obb_obb_distance, overlapping, v, {});
  EXPECT_EQ(w.cls, CaseClass::impl_bug);
  EXPECT_NE(w.parties[0].why.find("on_b lies"), std::string::npos) << w.parties[0].why;
}

// The generator reaches every sign and both sides of touching by a hair, parallel and skewed axes.
TEST(ObbObbDistanceKind, TheGeneratorMeetsEverySideOfTouching) {
  const exact::ExactRationalReference exact;
  int apart = 0, overlapping = 0, touching = 0, hair = 0, parallel = 0;
  for (std::uint64_t i = 0; i < 600; ++i) {
    RandomChoices c(i);
    const Input input = generate(QueryKind::obb_obb_distance, c);
    const auto& in = std::get<ObbObbDistanceInput>(input);
    const ExactVerdict v = exact.judge(input);
    if (v.contract != Contract::in || !v.decided) continue;
    const double d = v.answer.params.at(0);
    apart += d > 0, overlapping += d < 0, touching += d == 0;
    const double size = std::max(max_abs(in.a.half), max_abs(in.b.half));
    hair += d != 0 && std::fabs(d) < 0x1p-30 * size;
    parallel += in.a.axes == in.b.axes;
  }
  EXPECT_GT(apart, 50);
  EXPECT_GT(overlapping, 50);
  EXPECT_GT(touching, 10);
  EXPECT_GT(hair, 10);
  EXPECT_GT(parallel, 20);
}

TEST(ObbObbDistanceKind, TheDomainReachesFrom0To2To500) {
  const exact::ExactRationalReference exact;
  const auto scaled = [](double s) {
    ObbObbDistanceInput in = kApart;
    for (Obb* b : {&in.a, &in.b}) b->center = s * b->center, b->half = s * b->half;
    return Input{in};
  };
  EXPECT_EQ(exact.judge(scaled(0x1p-1000)).contract, Contract::in);
  EXPECT_EQ(exact.judge(scaled(0x1p400)).contract, Contract::in);
  EXPECT_EQ(exact.judge(scaled(0x1p600)).contract, Contract::unspecified);
  ObbObbDistanceInput skewed = kApart;
  skewed.b.axes.col[0].y = 0x1p-20;  // far beyond the orthonormality tolerance
  EXPECT_EQ(exact.judge(Input{skewed}).contract, Contract::unspecified);
  for (double s : {0x1p-1000, 0x1p400}) {
    EXPECT_EQ(classify(QueryKind::obb_obb_distance, ask_library(scaled(s)), exact.judge(scaled(s)), {}).cls, CaseClass::agree);
  }
}

}  // namespace
}  // namespace cc::harness
