// Evaluating with the opinions asked in a child: a child that dies says how, and the caller
// goes on whole.
#include "harness/processes/evaluate_in_child.h"

#include <gtest/gtest.h>

#include "harness/crashing_opinions.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {


TEST(EvaluateInChild, AChildThatDiesSaysHowAndLeavesTheCallerWhole) {
  const exact::ExactRationalReference exact;
  std::string how;
  EXPECT_FALSE(evaluate_in_child(kOverlapping, exact, CrashingOpinions{}, 0, &how).has_value());
  EXPECT_EQ(how, "killed by signal 11 (Segmentation fault)");
}

}  // namespace
}  // namespace cc::harness
