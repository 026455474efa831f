// A case whose process died is rebuilt one way, whoever rebuilds it (the campaign, any command):
// the party that died fails, nothing is invented for the parties not asked, and a time-out is
// never an answer.
#include "harness/judging/evaluate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "harness/crashing_opinions.h"
#include "harness/judging/replay.h"
#include "harness/model/library.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

constexpr Band kBand = CrashingOpinions::kBand;


TEST(EvaluationAfterDeath, InTheSecondOpinionsEachFailedTheLibraryAndExactAnswered) {
  const exact::ExactRationalReference exact;
  const Evaluation e =
      evaluation_after_death(kOverlapping, exact, CrashingOpinions{}, DiedIn::second_opinions,
                             "killed by signal 11 (Segmentation fault)");
  EXPECT_TRUE(e.library_failure.empty());
  EXPECT_TRUE(e.library.hit);
  EXPECT_TRUE(e.exact.decided);
  ASSERT_EQ(e.opinions.size(), 2u);
  for (const Opinion& o : e.opinions) {
    EXPECT_EQ(o.status, Opinion::Status::failed);
    EXPECT_EQ(o.detail, "killed by signal 11 (Segmentation fault) in the second opinions (FCL/libccd, Bullet, ODE)");
  }
  EXPECT_EQ(e.verdict.cls, CaseClass::oracle_crash);
}

TEST(EvaluationAfterDeath, ATimeOutIsTimedOutNeverAnAnswer) {
  const exact::ExactRationalReference exact;
  const Evaluation e = evaluation_after_death(kOverlapping, exact, CrashingOpinions{}, DiedIn::second_opinions,
                                              "timed out: ran past its time limit");
  for (const Opinion& o : e.opinions) EXPECT_EQ(o.status, Opinion::Status::timed_out);
  EXPECT_EQ(e.verdict.cls, CaseClass::oracle_crash);
}

TEST(EvaluationAfterDeath, InTheLibraryItsFailureAndNoOpinion) {
  const exact::ExactRationalReference exact;
  const Evaluation e = evaluation_after_death(kOverlapping, exact, CrashingOpinions{}, DiedIn::library, "exited with status 3");
  EXPECT_EQ(e.library_failure, "exited with status 3 in the library");
  EXPECT_TRUE(e.opinions.empty());
  // The exact reference was never asked where the library died: it is not asked here either.
  EXPECT_FALSE(e.exact.decided);
  EXPECT_TRUE(std::isnan(e.exact.margin));
  EXPECT_EQ(e.exact.note, "not computed: exited with status 3 in the library");
  EXPECT_EQ(e.verdict.cls, CaseClass::impl_bug);
  ASSERT_FALSE(e.verdict.parties.empty());
  EXPECT_EQ(e.verdict.parties[0].standing, Standing::failed);
}

// The same two parties, answering as the library does.
class Answering final : public SecondOpinion {
 public:
  std::vector<Opinion> opinions(const Input& in) const override {
    return {{"fcl.AABBd::overlap", Opinion::Status::answered, ask_library(in), "", kBand},
            {"bullet.x", Opinion::Status::answered, ask_library(in), "", kBand}};
  }
  std::vector<PartyBand> parties(QueryKind) const override { return {{"fcl.AABBd::overlap", kBand}, {"bullet.x", kBand}}; }
};

Case stored(const Evaluation& e) {
  Case c;
  c.input = kOverlapping;
  c.library = e.library;
  c.library_failure = e.library_failure;
  c.exact = e.exact;
  c.opinions = e.opinions;
  c.cls = e.verdict.cls;
  return c;
}

// A time-out depends on the machine: a case stored as it was cut off, in whichever party,
// replays unchanged when every party now returns, and a case stored whole replays unchanged
// when one is cut off now. A crash is no time-out: it is still a change.
TEST(EvaluationAfterDeath, ATimeOutAnywhereReplaysUnchangedBothWays) {
  const exact::ExactRationalReference exact;
  const Answering second;
  const Evaluation whole = evaluate(kOverlapping, exact, &second);
  ASSERT_EQ(whole.verdict.cls, CaseClass::agree);
  for (const DiedIn where : {DiedIn::library, DiedIn::exact, DiedIn::second_opinions}) {
    const Evaluation cut = evaluation_after_death(kOverlapping, exact, second, where, "timed out: ran past its time limit");
    EXPECT_TRUE(replay_changes(stored(cut), whole).empty()) << died_in_name(where) << ": " << replay_changes(stored(cut), whole)[0];
    EXPECT_TRUE(replay_changes(stored(whole), cut).empty()) << died_in_name(where) << ": " << replay_changes(stored(whole), cut)[0];
    const Evaluation crashed = evaluation_after_death(kOverlapping, exact, second, where, "killed by signal 11 (Segmentation fault)");
    EXPECT_FALSE(replay_changes(stored(crashed), whole).empty()) << died_in_name(where);
  }
  // The second opinions cut off leave the exact verdict asked on both sides: still compared.
  Case c = stored(evaluation_after_death(kOverlapping, exact, second, DiedIn::second_opinions, "timed out: ran past its time limit"));
  c.exact.margin = 0.125;
  const std::vector<std::string> changes = replay_changes(c, whole);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_NE(changes[0].find("the exact margin changed"), std::string::npos) << changes[0];
}

TEST(EvaluationAfterDeath, InTheExactReferenceNoVerdict) {
  const exact::ExactRationalReference exact;
  const Evaluation e = evaluation_after_death(kOverlapping, exact, CrashingOpinions{}, DiedIn::exact, "killed by signal 6 (Aborted)");
  EXPECT_TRUE(e.library.hit);
  EXPECT_FALSE(e.exact.decided);
  EXPECT_TRUE(std::isnan(e.exact.margin));
  EXPECT_EQ(e.exact.note, "killed by signal 6 (Aborted) in the exact reference");
  EXPECT_TRUE(e.opinions.empty());
  EXPECT_EQ(e.verdict.cls, CaseClass::undecided);
}

}  // namespace
}  // namespace cc::harness
