// The generators meet the boundary: touching (exact margin 0), parallel and degenerate
// configurations for every kind, and inputs outside the domain when asked.
#include "harness/generate.h"

#include <gtest/gtest.h>

#include "harness/features.h"
#include "harness/input_json.h"
#include "oracle/exact/exact_reference.h"
#include "case_budget.h"
#include "test_paths.h"

namespace cc::harness {
namespace {

const GenerateOptions kOptions{.mesh_folder = test::fcl_mesh_folder()};

TEST(Generate, IsDeterministic) {
  for (QueryKind kind : kAllQueryKinds) {
    RandomChoices a(9), b(9);
    EXPECT_EQ(input_to_json(generate(kind, a, kOptions)).dump(), input_to_json(generate(kind, b, kOptions)).dump());
  }
}

TEST(Generate, ZeroChoicesGiveASimpleCaseInTheDomain) {
  const exact::ExactRationalReference exact;
  for (QueryKind kind : kAllQueryKinds) {
    ReplayChoices zeros({});
    const ExactVerdict v = exact.judge(generate(kind, zeros, kOptions));
    EXPECT_EQ(v.contract, Contract::in) << name(kind) << ": " << v.note;
  }
}

TEST(Generate, MeetsTouchingParallelAndDegenerateCases) {
  const exact::ExactRationalReference exact;
  for (QueryKind kind : kAllQueryKinds) {
    int touching = 0, parallel = 0, degenerate = 0, hits = 0, misses = 0;
    const int n = test::case_budget(kind, 2000);
    for (int i = 0; i < n; ++i) {
      RandomChoices c(static_cast<std::uint64_t>(i));
      const Input input = generate(kind, c, kOptions);
      const ExactVerdict v = exact.judge(input);
      const Features f = features_of(input, v);
      touching += f.touching;
      parallel += f.parallel;
      degenerate += f.degenerate;
      if (v.contract == Contract::in) (v.answer.hit ? hits : misses) += 1;
    }
    EXPECT_GT(touching, n / 50) << name(kind);
    if (parallel_applies(kind)) {
      EXPECT_GT(parallel, n / 50) << name(kind);
    }
    EXPECT_GT(degenerate, n / 50) << name(kind);
    EXPECT_GT(hits, n / 10) << name(kind);
    EXPECT_GT(misses, n / 10) << name(kind);
  }
}

TEST(Generate, OutOfContractCasesLeaveTheDomain) {
  const exact::ExactRationalReference exact;
  for (QueryKind kind : kAllQueryKinds) {
    int outside = 0;
    const int n = test::case_budget(kind, 500);
    for (int i = 0; i < n; ++i) {
      RandomChoices c(static_cast<std::uint64_t>(i));
      outside += exact.judge(generate(kind, c, {.out_of_contract = true, .mesh_folder = test::fcl_mesh_folder()})).contract != Contract::in;
    }
    EXPECT_GT(outside, n / 20) << name(kind);
  }
}

}  // namespace
}  // namespace cc::harness
