#include "harness/judging/bound_coverage.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "collide/bound_records.h"
#include "harness/generation/generate.h"
#include "oracle/exact/exact_reference.h"
#include "test_paths.h"

namespace cc::harness {
namespace {

const GenerateOptions kOptions{.mesh_folder = test::fcl_mesh_folder()};

// An exact reference that finds every case touching and reports the given errors.
class Fixed final : public ExactReference {
 public:
  explicit Fixed(std::vector<TermError> errors, double margin = 0) : errors_(std::move(errors)), margin_(margin) {}
  ExactVerdict judge(const Input&) const override {
    ExactVerdict v;
    v.margin = margin_;
    return v;
  }
  Explanation explain(const Input&) const override { return {}; }
  std::vector<TermError> bound_errors(const bounds::Records&) const override { return errors_; }

 private:
  std::vector<TermError> errors_;
  double margin_;
};

const Input kObbCase = ObbObbInput{{{0, 0, 0}, {1, 1, 1}, {}}, {{2, 0, 0}, {1, 1, 1}, {}}};

const TermCoverage& row(const std::vector<TermCoverage>& rows, std::string_view quantity, std::string_view term) {
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const TermCoverage& r) { return r.quantity == quantity && r.term == term; });
  EXPECT_NE(it, rows.end()) << quantity << " " << term;
  return *it;
}

TEST(ProbeLibrary, EveryCertifiedQueryRecordsItsQuantities) {
  for (QueryKind kind : kAllQueryKinds) {
    ReplayChoices zeros({});
    const auto records = probe_library(generate(kind, zeros, kOptions));
    const bool certified = std::any_of(expected_terms().begin(), expected_terms().end(),
                                       [&](const ExpectedTerm& e) { return e.kind == kind; });
    EXPECT_EQ(records.empty(), !certified) << name(kind);
  }
  // A mesh query's two objects are measured apart.
  ReplayChoices zeros({});
  EXPECT_EQ(probe_library(generate(QueryKind::mesh_mesh, zeros, kOptions)).size(), 2u);
}

TEST(BoundCoverage, KeepsTheClosestApproachAndFlagsTermsNeverApproachedOrExceeded) {
  BoundCoverage coverage;
  const double rounding = 64 * fp::u;
  EXPECT_TRUE(coverage.add(kObbCase, Fixed({{"axis", "rounding", rounding / 4, rounding},
                                           {"axis", "frame", 0x1p-70, 0x1p-45},
                                           {"axis", "total", rounding / 4, rounding + 0x1p-45}})).measured);
  const CaseCoverage second = coverage.add(kObbCase, Fixed({{"axis", "rounding", rounding / 2, rounding}}));
  EXPECT_EQ(second.largest, 0.5);
  EXPECT_EQ(second.where, "test_obb_obb axis rounding");
  const QueryKind obb[] = {QueryKind::obb_obb};
  auto rows = coverage.rows(obb);
  ASSERT_EQ(rows.size(), 3u);  // the expected rows of obb_obb, in order
  EXPECT_EQ(row(rows, "axis", "rounding").closest, 0.5);
  EXPECT_EQ(row(rows, "axis", "rounding").quantities, 2);
  EXPECT_EQ(row(rows, "axis", "rounding").cases, 2);
  EXPECT_TRUE(row(rows, "axis", "rounding").ok());
  EXPECT_FALSE(row(rows, "axis", "frame").ok());  // 2^-25 of its term: never approached
  EXPECT_TRUE(row(rows, "axis", "total").ok());
  EXPECT_NE(format_coverage(rows).find("never approached"), std::string::npos);

  // A term that does not cover its error (even where it cannot decide), and a bound that does
  // not hold.
  TermError off{"axis", "rounding", 2 * rounding, rounding};
  off.decisive = false;
  EXPECT_EQ(coverage.add(kObbCase, Fixed({off})).largest, 2);
  EXPECT_FALSE(coverage.rows(obb)[0].ok());
  EXPECT_EQ(coverage.add(kObbCase, Fixed({{"axis", "frame", 0x1p-40, 0}, {"axis", "total", 2, 1}})).largest, INFINITY);
  rows = coverage.rows(obb);
  EXPECT_FALSE(row(rows, "axis", "frame").ok());
  EXPECT_FALSE(row(rows, "axis", "total").ok());
  EXPECT_NE(row(rows, "axis", "total").largest_case.find("center"), std::string::npos);  // its inputs
  EXPECT_NE(format_coverage(rows).find("EXCEEDED"), std::string::npos);
}

TEST(BoundCoverage, CountsATermOnlyAtTheDecisionAndErrorsBeyondTheSubnormalAllowance) {
  BoundCoverage coverage;
  TermError off{"axis", "rounding", 1, 2};
  off.decisive = false;
  coverage.add(kObbCase, Fixed({off}));                                       // not at its decision
  coverage.add(kObbCase, Fixed({{"axis", "frame", 1, 2}}, -0x1p-20));         // the case far from touching
  coverage.add(kObbCase, Fixed({{"axis", "total", fp::subnormal_slack, fp::subnormal_slack}}));
  coverage.add(kObbCase, Fixed({{"axis", "frame", fp::subnormal_slack, 0}}));  // underflow only
  const QueryKind obb[] = {QueryKind::obb_obb};
  const auto rows = coverage.rows(obb);
  EXPECT_EQ(row(rows, "axis", "rounding").quantities, 0);
  EXPECT_EQ(row(rows, "axis", "frame").quantities, 1);
  EXPECT_EQ(row(rows, "axis", "frame").closest, 0);
  EXPECT_EQ(row(rows, "axis", "total").closest, 1);
  EXPECT_TRUE(row(rows, "axis", "total").ok());
  EXPECT_NE(format_coverage(rows).find("not measured"), std::string::npos);
}

TEST(BoundCoverage, SkipsCasesOutsideTheDomain) {
  BoundCoverage coverage;
  const exact::ExactRationalReference exact;
  EXPECT_FALSE(coverage.add(ObbObbInput{{{NAN, 0, 0}, {1, 1, 1}, {}}, {}}, exact).measured);
  EXPECT_TRUE(coverage.add(kObbCase, exact).measured);
}

TEST(BoundCoverage, NamesTheTestOfEachQuantity) {
  EXPECT_EQ(test_of(QueryKind::moving_obb, "aabb time"), "sweep_aabb_aabb");
  EXPECT_EQ(test_of(QueryKind::moving_obb, "axis"), "sweep_obb_obb");
  EXPECT_EQ(test_of(QueryKind::ray_mesh, "face hit"), "ray_mesh_closest");
  EXPECT_EQ(test_of(QueryKind::mesh_mesh, "cube"), "object_bounds");
}

}  // namespace
}  // namespace cc::harness
