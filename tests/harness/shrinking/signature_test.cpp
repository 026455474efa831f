#include "harness/shrinking/signature.h"

#include <gtest/gtest.h>

#include "harness/judging/evaluate.h"
#include "oracle/fcl/fcl_oracle.h"

namespace cc::harness {
namespace {

Evaluation with(bool exact_hit, bool library_hit, bool fcl_hit) {
  Evaluation e;
  e.exact.answer.hit = exact_hit;
  e.exact.margin = exact_hit ? 0.25 : -0.25;
  e.library.hit = library_hit;
  e.opinions = {{"fcl.Intersect::intersect_Triangle", Opinion::Status::answered, {fcl_hit, {}, {}, {}}, ""}};
  restore_bands(e.opinions, fcl_oracle::FclSecondOpinion(), QueryKind::tri_tri);
  e.verdict = classify(QueryKind::tri_tri, e.library, e.exact, e.opinions);
  return e;
}

TEST(Signature, NamesWhoDisagreesAndHow) {
  EXPECT_EQ(signature_of(QueryKind::tri_tri, with(false, false, true)),
            "tri_tri oracle_defect exact=miss fcl.Intersect::intersect_Triangle:wrong:hit");
  EXPECT_EQ(signature_of(QueryKind::tri_tri, with(true, true, true)), "tri_tri agree exact=hit");
  EXPECT_NE(signature_of(QueryKind::tri_tri, with(true, true, false)),
            signature_of(QueryKind::tri_tri, with(false, false, true)));
}

TEST(FindingKey, AddsFeaturesAndTheMarginsDecade) {
  const Triangle point{{Vec3{0, 0, 0}, Vec3{0, 0, 0}, Vec3{0, 0, 0}}};
  const Triangle other{{Vec3{0, 0, 1}, Vec3{0, 0, 1}, Vec3{0, 0, 1}}};
  const std::string key = finding_key(TriTriInput{point, other}, with(false, false, true));
  EXPECT_NE(key.find("degenerate"), std::string::npos);
  EXPECT_NE(key.find("1e-1"), std::string::npos);
}

}  // namespace
}  // namespace cc::harness
