// Metamorphic properties, exact in floating point so no oracle is needed: swapping the two
// shapes, permuting the axes, flipping the sign of an axis and scaling by a power of two give
// the library's answer bit for bit (ray parameters included). Where a relation does not apply
// (no second shape; a k-DOP direction set not closed under it: 16 under both, 24 under flips)
// it is skipped; mesh queries take only the permutation of the world's axes. Scaling is checked
// on inputs whose values lie in [2^-250, 2^250] (others flushed to 0), where no intermediate
// result of the library underflows or overflows.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "harness/input_json.h"
#include "harness/library.h"
#include "harness/metamorphic.h"
#include "oracle/exact/exact_reference.h"
#include "case_budget.h"
#include "properties/property.h"

namespace cc::test {
namespace {

using namespace harness;

struct Case {
  QueryKind kind;
  Relation relation;
};

class Metamorphic : public ::testing::TestWithParam<Case> {};

TEST_P(Metamorphic, TheAnswerIsUnchanged) {
  const QueryKind kind = GetParam().kind;
  const Relation relation = GetParam().relation;  // not a structured binding: the lambda below captures it
  const exact::ExactRationalReference exact;
  const std::string property = std::string(name(kind)) + ": " + std::string(to_string(relation));
  Met met;
  int applied = 0;
  const int cases = case_budget(kind, 1000);
  const bool passed = check_property(property, kind, 0, cases, met, [&](const Input& generated) {
    const Input input = relation == Relation::scale ? flush_extremes(generated) : generated;
    met.count(features_of(input, exact.judge(input)));
    int parameter = 0;
    switch (relation) {
      case Relation::permute_axes: parameter = *rc::gen::inRange(1, 6); break;
      case Relation::flip_axis: parameter = *rc::gen::inRange(0, 3); break;
      case Relation::scale: parameter = *rc::gen::element(-8, -3, -1, 1, 2, 7); break;
      case Relation::swap_shapes: break;
    }
    const auto transformed = transform(input, relation, parameter);
    if (!transformed) return;
    ++applied;
    const Answer before = ask_library(input), after = ask_library(*transformed);
    if (!(before == after)) {
      RC_FAIL("the answer changed (" + std::to_string(before.hit) + " -> " + std::to_string(after.hit) +
              ") under parameter " + std::to_string(parameter) + "\n  inputs: " + input_to_json(input).dump());
    }
  });
  EXPECT_TRUE(passed) << property;
  EXPECT_GT(applied, cases / 10) << property << ": the relation hardly ever applied";
  expect_met_the_boundary(property, kind, met);
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (QueryKind kind : kAllQueryKinds) {
    for (Relation r : {Relation::swap_shapes, Relation::permute_axes, Relation::flip_axis, Relation::scale}) {
      if (relation_applies(kind, r)) cases.push_back({kind, r});
    }
  }
  return cases;
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string r(to_string(info.param.relation));
  for (char& c : r) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return std::string(name(info.param.kind)) + "_" + r;
}

INSTANTIATE_TEST_SUITE_P(EveryQueryAndRelation, Metamorphic, ::testing::ValuesIn(all_cases()), case_name);

}  // namespace
}  // namespace cc::test
