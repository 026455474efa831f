// Differential properties: the library is never an impl_bug against the exact reference, in
// its domain (within its band) and outside it (its documented answers). Second opinions (FCL)
// are left to the campaign: a crash or hang there must not take down the test process.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "harness/judging/configurations.h"
#include "harness/judging/evaluate.h"
#include "harness/formats/input_json.h"
#include "oracle/exact/exact_reference.h"
#include "case_budget.h"
#include "properties/property.h"

namespace cc::test {
namespace {

using namespace harness;

class Differential : public ::testing::TestWithParam<QueryKind> {};

TEST_P(Differential, TheLibraryIsNeverAnImplBug) {
  const QueryKind kind = GetParam();
  const exact::ExactRationalReference exact;
  const std::string property = std::string(name(kind)) + " is never an impl_bug";
  Met met;
  // A primitive case costs about 0.1 ms with the exact reference: thousands of them find the
  // rare boundary that only a few generated cases sit on (a segment ending exactly on a face
  // where its slab parameter rounds past it, touching balls whose squares round apart).
  const int cases = case_budget(kind, 4000, 300);
  const bool passed = check_property(property, kind, 10, cases, met, [&](const Input& input) {
    const Evaluation e = evaluate(input, exact, nullptr);
    met.count(features_of(input, e.exact));
    met.count(configurations_of(input, e.exact));
    if (e.verdict.cls == CaseClass::impl_bug) {
      RC_FAIL("impl_bug: " + e.verdict.parties[0].why + "\n  inputs: " + input_to_json(input).dump());
    }
  }, &exact);
  EXPECT_TRUE(passed) << property;
  expect_met_the_boundary(property, kind, met);
  expect_met_every_configuration(property, kind, met);
}

INSTANTIATE_TEST_SUITE_P(EveryQuery, Differential, ::testing::ValuesIn(kAllQueryKinds),
                         [](const auto& p) { return std::string(name(p.param)); });

}  // namespace
}  // namespace cc::test
