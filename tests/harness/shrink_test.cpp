#include "harness/shrink.h"

#include <gtest/gtest.h>

#include "harness/library.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

TEST(Complexity, OrdersZeroIntegersHalvesThenMantissaBits) {
  EXPECT_LT(complexity(0.0), complexity(-0.0));
  EXPECT_LT(complexity(-0.0), complexity(1.0));
  EXPECT_LT(complexity(1.0), complexity(-1.0));
  EXPECT_LT(complexity(2.0), complexity(3.0));
  EXPECT_LT(complexity(1000.0), complexity(0.5));
  EXPECT_LT(complexity(0.5), complexity(0.1));
  EXPECT_LT(complexity(0.75), complexity(0.1));
  EXPECT_LT(complexity(0x1p30), complexity(0.1));
  EXPECT_LT(complexity(0.1), complexity(NAN));
}

TEST(ComplexValues, CountsWhatIsNotASmallIntegerOrAHalf) {
  EXPECT_EQ(complex_values(SphereSphereInput{{{0, 1, -2}, 0.5}, {{1024, 0.25, 0.1}, 1e9}}), 3);
}

// An evaluation that only the exact reference and the library make, with a planted
// disagreement: a "second opinion" that says hit whenever the spheres' radii sum above 1.
Evaluation planted(const Input& in) {
  static const exact::ExactRationalReference exact;
  Evaluation e;
  e.library = ask_library(in);
  e.exact = exact.judge(in);
  const auto& s = std::get<SphereSphereInput>(in);
  e.opinions = {{"fcl.collide(Sphere,Sphere)", Opinion::Status::answered, {s.a.radius + s.b.radius > 1, {}}, ""}};
  e.verdict = classify(QueryKind::sphere_sphere, e.library, e.exact, e.opinions);
  return e;
}

TEST(Shrink, KeepsTheDisagreementAndSimplifiesTheValues) {
  const Input start = SphereSphereInput{{{0.1234567, -7.5e3, 3.3}, 0.9876}, {{11.11, 0.2, 9.87e5}, 0.33}};
  const Evaluation e = planted(start);
  ASSERT_EQ(e.verdict.cls, CaseClass::oracle_defect);  // apart, but the planted party says hit
  const ShrinkResult r = shrink(start, e, planted);
  EXPECT_EQ(r.evaluation.verdict.cls, CaseClass::oracle_defect);
  EXPECT_EQ(complex_values(r.input), 0);
  const auto& s = std::get<SphereSphereInput>(r.input);
  EXPECT_GT(s.a.radius + s.b.radius, 1);  // still the planted disagreement
  EXPECT_LE(r.attempts, 4000);
}

TEST(Shrink, RespectsTheAttemptBudget) {
  const Input start = SphereSphereInput{{{0.1234567, -7.5e3, 3.3}, 0.9876}, {{11.11, 0.2, 9.87e5}, 0.33}};
  EXPECT_LE(shrink(start, planted(start), planted, 5).attempts, 5);
}

}  // namespace
}  // namespace cc::harness
