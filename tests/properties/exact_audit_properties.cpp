// The exact reference agrees with CGAL's exact kernel (oracle/cgal) on every kind CGAL answers:
// a few hundred generated cases per kind, biased toward touching, parallel and degenerate shapes
// as the campaign's are, and the generators must meet each of those (the touching ones at an
// exact margin of 0) for the agreement to mean something. `crosscheck audit-exact` runs the same
// for a time budget.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "harness/formats/input_json.h"
#include "harness/judging/features.h"
#include "oracle/cgal/exact_audit.h"
#include "oracle/exact/exact_reference.h"
#include "properties/property.h"

namespace cc::test {
namespace {

using namespace harness;

TEST(ExactAudit, TheExactReferenceAgreesWithCgalOnEveryKindItAnswers) {
  const exact::ExactRationalReference reference;
  int kinds = 0;
  for (QueryKind kind : kAllQueryKinds) {
    if (!cgal::answers(kind)) continue;
    ++kinds;
    const std::string property = std::string(name(kind)) + ": the exact reference agrees with CGAL";
    Met met;
    int compared = 0;
    const bool passed = check_property(property, kind, 10, 300, met, [&](const Input& in) {
      const cgal::Audit a = cgal::audit_case(in, reference);
      met.count(features_of(in, a.exact));
      if (a.outcome == cgal::AuditOutcome::disagree) RC_FAIL(a.why + " on " + input_to_json(in).dump());
      compared += a.outcome == cgal::AuditOutcome::agree;
    });
    EXPECT_TRUE(passed) << property;
    EXPECT_GT(compared, 200) << property << ": too few cases in contract";
    expect_met_the_boundary(property, kind, met);
  }
  EXPECT_EQ(kinds, 19);
}

}  // namespace
}  // namespace cc::test
