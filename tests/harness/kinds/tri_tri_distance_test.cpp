// The tri_tri_distance kind's unit: its answer (the distance, the witnesses and their bounds), its
// exact verdict and how a distance, a witness off its triangle, or witnesses too far apart are
// judged, for the library and for a peer, and its domain. (That its generator makes every
// configuration it declares is a property of every kind: tests/properties/property.h.)
#include "harness/kinds/tri_tri_distance.h"

#include <gtest/gtest.h>

#include "harness/judging/classify.h"
#include "harness/model/library.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

using Kind = Query<TriTriDistanceInput>;

const Triangle kBase{{Vec3{0, 0, 0}, Vec3{4, 0, 0}, Vec3{0, 4, 0}}};
// kBase lifted by 1: parallel faces, every point of the overlap of their shadows a closest pair.
const TriTriDistanceInput kLifted{kBase, {{Vec3{0, 0, 1}, Vec3{4, 0, 1}, Vec3{0, 4, 1}}}};

Opinion peer(std::vector<double> params, bool hit = false) {
  Opinion o;
  o.party = "peer";
  o.status = Opinion::Status::answered;
  o.answer = Answer::of(hit);
  o.answer.params = std::move(params);
  o.band = Band{0, BandSides::two_sided, 0x1p-40, "a test's"};
  return o;
}

TEST(TriTriDistanceKind, TheAnswerIsTheDistanceTheWitnessesAndTheirBounds) {
  const Answer a = Kind::ask(kLifted);
  EXPECT_FALSE(a.hit);
  ASSERT_EQ(a.params.size(), 9u);
  EXPECT_EQ(a.params[0], 1);
  EXPECT_EQ(a.params[3], 0);  // on_a in a's plane
  EXPECT_EQ(a.params[6], 1);  // on_b in b's
  EXPECT_GT(a.params[7], 0);
  EXPECT_LT(a.params[7], 0x1p-40);
  EXPECT_GT(a.params[8], 0);
  EXPECT_EQ(ask_library(Input{kLifted}), a);
  EXPECT_TRUE(Kind::ask({kBase, {{Vec3{1, 1, -1}, Vec3{1, 1, 1}, Vec3{2, 1, 1}}}}).hit);
}

TEST(TriTriDistanceKind, TheExactVerdictChecksTheDistanceAndTheWitnesses) {
  const exact::ExactRationalReference exact;
  const ExactVerdict v = exact.judge(Input{kLifted});
  ASSERT_EQ(v.contract, Contract::in);
  EXPECT_FALSE(v.answer.hit);
  EXPECT_EQ(v.answer.params, std::vector<double>{1});
  EXPECT_EQ(v.scale, 4);
  const Answer right = Kind::ask(kLifted);
  ASSERT_EQ(right.params.size(), 9u);
  EXPECT_EQ(classify(QueryKind::tri_tri_distance, right, v, {}).cls, CaseClass::agree);

  const auto why_wrong = [&](const Answer& said) {
    const Verdict w = classify(QueryKind::tri_tri_distance, said, v, {});
    EXPECT_EQ(w.cls, CaseClass::impl_bug);
    return w.parties[0].why;
  };
  Answer far = right;
  far.params[0] += 1000 * right.params[7];
  EXPECT_NE(why_wrong(far).find("distance"), std::string::npos);
  Answer off = right;
  off.params[3] = 1000 * right.params[8];  // on_a lifted off a by a thousand times its bound
  EXPECT_NE(why_wrong(off).find("on_a lies"), std::string::npos);
  Answer apart = right;
  apart.params[4] += 1;  // on_b slid along b: still on it, but farther from on_a than the distance
  EXPECT_NE(why_wrong(apart).find("points lie"), std::string::npos);
  Answer bound = right;
  bound.params[7] = -1;
  EXPECT_NE(why_wrong(bound).find("error bounds"), std::string::npos);
  Answer short_answer = right;
  short_answer.params.resize(5);
  EXPECT_NE(why_wrong(short_answer).find("gives 5 numbers"), std::string::npos);
}

TEST(TriTriDistanceKind, APeerIsJudgedByItsBandOfTheScale) {
  const exact::ExactRationalReference exact;
  const ExactVerdict v = exact.judge(Input{kLifted});
  // The band: 2^-40 of the scale (4) for the distance and each point.
  const Verdict near = classify(QueryKind::tri_tri_distance, Kind::ask(kLifted), v, {peer({1 + 0x1p-40, 1, 1, 0, 1, 1, 1})});
  EXPECT_EQ(near.cls, CaseClass::agree);
  const Verdict off = classify(QueryKind::tri_tri_distance, Kind::ask(kLifted), v, {peer({1 + 0x1p-36, 1, 1, 0, 1, 1, 1})});
  EXPECT_EQ(off.cls, CaseClass::oracle_defect);
  // Collision with no distance is judged on the hit: wrong for triangles apart by 1.
  EXPECT_EQ(classify(QueryKind::tri_tri_distance, Kind::ask(kLifted), v, {peer({}, true)}).cls, CaseClass::oracle_defect);
  EXPECT_EQ(classify(QueryKind::tri_tri_distance, Kind::ask(kLifted), v, {peer({}, false)}).cls, CaseClass::agree);
}

TEST(TriTriDistanceKind, TheDomainReachesFrom0To2To500) {
  const exact::ExactRationalReference exact;
  const auto scaled = [](double s) {
    TriTriDistanceInput in = kLifted;
    for (Triangle* t : {&in.a, &in.b}) {
      for (Vec3& p : t->v) p = s * p;
    }
    return Input{in};
  };
  EXPECT_EQ(exact.judge(scaled(0x1p-1000)).contract, Contract::in);
  EXPECT_EQ(exact.judge(scaled(0x1p400)).contract, Contract::in);
  EXPECT_EQ(exact.judge(scaled(0x1p600)).contract, Contract::unspecified);
  const Input tiny = scaled(0x1p-1000);
  EXPECT_EQ(classify(QueryKind::tri_tri_distance, ask_library(tiny), exact.judge(tiny), {}).cls, CaseClass::agree);
}

}  // namespace
}  // namespace cc::harness
