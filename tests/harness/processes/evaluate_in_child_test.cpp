// Evaluating with the opinions asked in a child: a child that dies says how, and the caller
// goes on whole.
#include "harness/processes/evaluate_in_child.h"

#include <gtest/gtest.h>

#include <csignal>

#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

constexpr Band kBand{0, BandSides::exact, 0, "comparisons of inputs only: exact"};

// Two parties that crash the process they are asked in.
class Crashing final : public SecondOpinion {
 public:
  std::vector<Opinion> opinions(const Input&) const override {
    std::raise(SIGSEGV);
    return {};
  }
  std::vector<PartyBand> parties(QueryKind) const override { return {{"fcl.AABBd::overlap", kBand}, {"bullet.x", kBand}}; }
};

const Input kOverlapping = AabbAabbInput{{{0, 0, 0}, {1, 1, 1}}, {{0.5, 0.5, 0.5}, {2, 2, 2}}};

TEST(EvaluateInChild, AChildThatDiesSaysHowAndLeavesTheCallerWhole) {
  const exact::ExactRationalReference exact;
  std::string how;
  EXPECT_FALSE(evaluate_in_child(kOverlapping, exact, Crashing{}, 0, &how).has_value());
  EXPECT_EQ(how, "killed by signal 11 (Segmentation fault)");
}

}  // namespace
}  // namespace cc::harness
