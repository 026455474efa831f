#include "harness/classify.h"

#include <gtest/gtest.h>

namespace cc::harness {
namespace {

ExactVerdict exact(bool hit, double margin, std::vector<double> params = {}) {
  ExactVerdict v;
  v.answer = {hit, std::move(params), {}, {}};
  v.margin = margin;
  return v;
}

Opinion said(const std::string& party, bool hit) { return {party, Opinion::Status::answered, {hit, {}, {}, {}}, ""}; }

const std::string kObb = "fcl.OBBd::overlap";

TEST(Classify, AgreeWhenEveryPartyMatches) {
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(true, 0.1), {said(kObb, true)}).cls, CaseClass::agree);
}

TEST(Classify, ALibraryMissForTouchingShapesIsAnImplBug) {
  const Verdict v = classify(QueryKind::obb_obb, {false, {}, {}, {}}, exact(true, 0), {said(kObb, true)});
  EXPECT_EQ(v.cls, CaseClass::impl_bug);
  EXPECT_EQ(v.parties[0].standing, Standing::wrong);
}

TEST(Classify, ALibraryHitJustApartIsBoundary) {
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(false, -0x1p-45), {said(kObb, false)}).cls,
            CaseClass::boundary);
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(false, -0x1p-30), {said(kObb, false)}).cls,
            CaseClass::impl_bug);
  // aabb_aabb has no band at all.
  EXPECT_EQ(classify(QueryKind::aabb_aabb, {true, {}, {}, {}}, exact(false, -0x1p-60), {}).cls, CaseClass::impl_bug);
}

TEST(Classify, ASecondOpinionWrongBeyondItsBandIsAnOracleDefect) {
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(true, 0.1), {said(kObb, false)}).cls,
            CaseClass::oracle_defect);
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(true, 0x1p-30), {said(kObb, false)}).cls,
            CaseClass::boundary);
  // The library wrong and FCL wrong: the library's bug comes first.
  EXPECT_EQ(classify(QueryKind::obb_obb, {false, {}, {}, {}}, exact(true, 0.1), {said(kObb, false)}).cls,
            CaseClass::impl_bug);
}

TEST(Classify, FailedAndInapplicableOpinions) {
  const Opinion failed{kObb, Opinion::Status::failed, {}, "did not return"};
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(true, 0.1), {failed}).cls, CaseClass::oracle_crash);
  const Opinion na{"libccd.GJK", Opinion::Status::not_applicable, {}, "a ray"};
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2}), {na}).cls, CaseClass::agree);
}

TEST(Classify, ALibraryPartyWithoutParametersIsJudgedOnItsHitAlone) {
  const Opinion batched{"library.test_ray_aabbs", Opinion::Status::answered, {true, {}, {}, {}}, ""};
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2}), {batched}).cls,
            CaseClass::agree);
  const Opinion misses{"library.test_ray_aabbs", Opinion::Status::answered, {false, {}, {}, {}}, ""};
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0, {1, 2}), {misses}).cls,
            CaseClass::impl_bug);
  const Opinion wrong_t{"library.test_ray_aabbs", Opinion::Status::answered, {true, {1, 2.001}, {}, {}}, ""};
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2}), {wrong_t}).cls,
            CaseClass::impl_bug);
  const Opinion failed{"library.test_ray_aabbs", Opinion::Status::failed, {}, "the avx2 kernel says hit"};
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2}), {failed}).cls,
            CaseClass::impl_bug);
}

TEST(Classify, RayParametersMustBeWithinTheirBand) {
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2 + 0x1p-51}), {}).cls,
            CaseClass::agree);
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2.001}), {}).cls,
            CaseClass::impl_bug);
}

TEST(Classify, OutOfContractChecksTheDocumentedAnswerOnly) {
  ExactVerdict documented = exact(false, NAN);
  documented.contract = Contract::documented;
  documented.note = "NaN input";
  EXPECT_EQ(classify(QueryKind::obb_obb, {false, {}, {}, {}}, documented, {said(kObb, true)}).cls, CaseClass::out_of_contract);
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, documented, {}).cls, CaseClass::impl_bug);
  ExactVerdict unspecified = exact(false, NAN);
  unspecified.contract = Contract::unspecified;
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, unspecified, {}).cls, CaseClass::out_of_contract);
  ExactVerdict undecided = exact(false, 0);
  undecided.decided = false;
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, undecided, {}).cls, CaseClass::undecided);
}

TEST(CaseClass, NamesRoundTrip) {
  for (CaseClass c : kAllClasses) EXPECT_EQ(case_class_named(to_string(c)), c);
  EXPECT_FALSE(case_class_named("bug").has_value());
}

}  // namespace
}  // namespace cc::harness
