// The campaign's supervision: a second opinion that crashes or hangs on some cases costs the
// campaign a worker, not the run; each such case is recorded as a finding and can be rebuilt. A
// worker whose second opinion abandoned a call is replaced before its next case, and a finding's
// second opinions are those its worker got, never asked in the campaign's own process. A worker
// killed by another process is interrupted, not blamed: its case is asked again.
#include "harness/processes/campaign.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <tuple>

#include "harness/formats/input_json.h"
#include "harness/model/library.h"
#include "harness/processes/interrupts.h"
#include "oracle/exact/exact_reference.h"
#include "temp_folder.h"

namespace cc::harness {
namespace {

std::size_t fingerprint(const Input& in) { return std::hash<std::string>{}(input_to_json(in).dump()); }
bool crashes_on(const Input& in) { return fingerprint(in) % 3001 == 0; }
bool hangs_on(const Input& in) { return fingerprint(in) % 4999 == 7; }

// An aabb_aabb campaign on two workers, against the exact reference and `second`.
template <class Second, class... Args>
CampaignResult aabb_campaign(CampaignOptions options, Args... args) {
  options.kinds = {QueryKind::aabb_aabb};
  options.workers = 2;
  const Oracles oracles{[] { return std::make_unique<exact::ExactRationalReference>(); },
                        [=] { return std::make_unique<Second>(args...); }};
  return run_campaign(options, oracles);
}

// The fake second opinions' party's band (exact, as the real fcl.AABBd::overlap's).
constexpr Band kBand{0, BandSides::exact, 0, "comparisons of inputs only: exact"};

// Answers like FCL's AABB test, but crashes or hangs on a few inputs.
class Unreliable final : public SecondOpinion {
 public:
  std::vector<Opinion> opinions(const Input& in) const override {
    if (crashes_on(in)) std::raise(SIGSEGV);
    while (hangs_on(in)) pause();
    return {{"fcl.AABBd::overlap", Opinion::Status::answered, ask_library(in), "", kBand}};
  }
  std::vector<PartyBand> parties(QueryKind) const override { return {{"fcl.AABBd::overlap", kBand}}; }
};

TEST(Campaign, SurvivesCrashesAndHangsInAnOracle) {
  CampaignOptions options;
  options.seconds = 3;
  options.seed = 5;
  options.case_timeout_seconds = 0.3;
  const CampaignResult r = aabb_campaign<Unreliable>(options);

  int crashes = 0, hangs = 0;
  for (const Finding& f : r.findings) {
    ASSERT_FALSE(f.crash.empty()) << "the library and the exact reference agree here";
    EXPECT_EQ(f.evaluation.verdict.cls, CaseClass::oracle_crash);
    // The finding's input is the case the worker was on.
    EXPECT_EQ(input_to_json(f.input).dump(),
              input_to_json(campaign_case(options.seed, f.kind, f.case_index, options.out_of_contract_percent)).dump());
    if (f.crash.find("hung") != std::string::npos) {
      ++hangs;
      EXPECT_TRUE(hangs_on(f.input)) << f.crash;
    } else {
      ++crashes;
      EXPECT_TRUE(crashes_on(f.input)) << f.crash;
    }
  }
  EXPECT_GT(crashes, 0);
  EXPECT_GT(hangs, 0);
  const KindTally& t = r.tallies.at(QueryKind::aabb_aabb);
  EXPECT_GT(t.cases, 10000u);
  EXPECT_EQ(t.count(CaseClass::oracle_crash), static_cast<std::uint64_t>(crashes + hangs));
  EXPECT_EQ(t.count(CaseClass::impl_bug), 0u);
}

bool exits_on(const Input& in) { return fingerprint(in) % 2003 == 11; }

// Answers like FCL's AABB test, but on a few inputs ends its process with status 0, as a peer's
// exit(0) would.
class Exiting final : public SecondOpinion {
 public:
  std::vector<Opinion> opinions(const Input& in) const override {
    if (exits_on(in)) std::_Exit(0);
    return {{"fcl.AABBd::overlap", Opinion::Status::answered, ask_library(in), "", kBand}};
  }
  std::vector<PartyBand> parties(QueryKind) const override { return {{"fcl.AABBd::overlap", kBand}}; }
};

TEST(Campaign, AnExitWithStatusZeroInTheMiddleOfACaseIsAFindingNotTheEndOfTheRun) {
  CampaignOptions options;
  options.seconds = 2;
  options.seed = 7;
  const CampaignResult r = aabb_campaign<Exiting>(options);
  EXPECT_GT(r.seconds, 1.9);
  int exits = 0;
  for (const Finding& f : r.findings) {
    EXPECT_TRUE(exits_on(f.input)) << f.crash;
    EXPECT_EQ(f.crash, "exited with status 0 in the second opinions (FCL/libccd, Bullet, ODE)");
    EXPECT_EQ(f.evaluation.verdict.cls, CaseClass::oracle_crash);
    ++exits;
  }
  EXPECT_GT(exits, 1);
  EXPECT_GT(r.tallies.at(QueryKind::aabb_aabb).cases, 5000u);
}

// Answers like FCL's AABB test, but on a few inputs sets a timer and waits for it: its SIGALRM,
// sent by no process, ends the worker as it would without a handler. Each case it is set in
// is marked in `folder`, which outlives the worker.
class WaitingForATimer final : public SecondOpinion {
 public:
  explicit WaitingForATimer(std::filesystem::path folder) : folder_(std::move(folder)) {}
  std::vector<Opinion> opinions(const Input& in) const override {
    if (exits_on(in)) {
      std::ofstream(folder_ / std::to_string(fingerprint(in))) << "x";
      ualarm(1000, 0);
      pause();
    }
    return {{"fcl.AABBd::overlap", Opinion::Status::answered, ask_library(in), "", kBand}};
  }
  std::vector<PartyBand> parties(QueryKind) const override { return {{"fcl.AABBd::overlap", kBand}}; }

 private:
  std::filesystem::path folder_;
};

TEST(Campaign, AFatalSignalNoProcessSentIsTakenNotLost) {
  const test::TempFolder folder("crosscheck_timer");
  CampaignOptions options;
  options.seconds = 2;
  options.seed = 7;
  const CampaignResult r = aabb_campaign<WaitingForATimer>(options, folder.path());
  const auto timers = std::distance(std::filesystem::directory_iterator(folder.path()), {});
  ASSERT_GT(timers, 3);  // (a lost signal resets the handler: the next one in the same worker is taken)
  // Every timer is a finding (the last one may have gone off as the run stopped).
  EXPECT_GE(static_cast<long>(r.findings.size()), timers - 1) << "a timer's signal was lost";
  for (const Finding& f : r.findings) {
    EXPECT_TRUE(exits_on(f.input)) << f.crash;
    EXPECT_EQ(f.crash, "killed by signal 14 (Alarm clock) in the second opinions (FCL/libccd, Bullet, ODE)");
  }
  EXPECT_EQ(r.asked_again, 0u);
}

// Answers like FCL's AABB test, but on a few inputs gives an opinion with no band, which judging
// the case refuses (an exception no party threw): the worker dies between cases, in no party.
class Bandless final : public SecondOpinion {
 public:
  std::vector<Opinion> opinions(const Input& in) const override {
    if (exits_on(in)) return {{"fcl.AABBd::overlap", Opinion::Status::answered, ask_library(in), "", std::nullopt}};
    return {{"fcl.AABBd::overlap", Opinion::Status::answered, ask_library(in), "", kBand}};
  }
  std::vector<PartyBand> parties(QueryKind) const override { return {{"fcl.AABBd::overlap", kBand}}; }
};

// Dying between cases is the harness's own failure, which no case can hold: a problem of the
// run, never a finding; a slot whose workers keep dying so is not given another for ever.
TEST(Campaign, ADeathBetweenCasesIsAProblemOfTheRunNotAFinding) {
  CampaignOptions options;
  options.seconds = 2;
  options.seed = 7;
  const CampaignResult r = aabb_campaign<Bandless>(options);
  EXPECT_TRUE(r.findings.empty()) << r.findings.front().crash;
  ASSERT_FALSE(r.problems.empty());
  EXPECT_LE(r.problems.size(), 6u) << "at most 3 per slot";
  for (const std::string& p : r.problems) {
    EXPECT_NE(p.find("exited with status 70 between cases, after aabb_aabb case "), std::string::npos) << p;
    EXPECT_NE(p.find("(the harness's own failure: no party was asking)"), std::string::npos) << p;
  }
}

bool abandoned_on(const Input& in) { return fingerprint(in) % 997 == 3; }

// Answers like FCL's AABB test, but on a few inputs a call is abandoned (a failed opinion), after
// which every answer of the same process is wrong, as a damaged heap could make it.
class DamagedAfterAbandoning final : public SecondOpinion {
 public:
  std::vector<Opinion> opinions(const Input& in) const override {
    if (abandoned_on(in)) {
      ++abandoned_;
      return {{"fcl.AABBd::overlap", Opinion::Status::failed, {}, "did not return within the time limit", kBand}};
    }
    Answer a = ask_library(in);
    if (abandoned_ > 0) a.hit = !a.hit;
    return {{"fcl.AABBd::overlap", Opinion::Status::answered, a, "", kBand}};
  }
  std::vector<PartyBand> parties(QueryKind) const override { return {{"fcl.AABBd::overlap", kBand}}; }
  int abandoned_calls() const override { return abandoned_; }

 private:
  mutable int abandoned_ = 0;
};

TEST(Campaign, ReplacesAWorkerAfterAnAbandonedCall) {
  CampaignOptions options;
  options.seconds = 2;
  options.seed = 9;
  options.out_of_contract_percent = 0;
  const CampaignResult r = aabb_campaign<DamagedAfterAbandoning>(options);
  // Only the abandoned cases are findings: no case ran in a worker after its abandoned call.
  int abandoned = 0;
  for (const Finding& f : r.findings) {
    EXPECT_TRUE(f.crash.empty()) << f.crash;
    EXPECT_TRUE(abandoned_on(f.input)) << "case " << f.case_index << " ran in a damaged worker";
    abandoned += abandoned_on(f.input);
  }
  EXPECT_GT(abandoned, 1);  // so workers were replaced and the campaign went on
  EXPECT_GT(r.tallies.at(QueryKind::aabb_aabb).cases, 5000u);
}

bool disagrees_on(const Input& in) { return fingerprint(in) % 499 == 5; }

// Disagrees with the library on a few inputs, and crashes whenever it is asked in the process
// that runs the campaign (the test's own).
class CrashesInTheCampaignProcess final : public SecondOpinion {
 public:
  explicit CrashesInTheCampaignProcess(pid_t campaign) : campaign_(campaign) {}
  std::vector<Opinion> opinions(const Input& in) const override {
    if (::getpid() == campaign_) std::raise(SIGSEGV);
    Answer a = ask_library(in);
    if (disagrees_on(in)) a.hit = !a.hit;
    return {{"fcl.AABBd::overlap", Opinion::Status::answered, a, "", kBand}};
  }
  std::vector<PartyBand> parties(QueryKind) const override { return {{"fcl.AABBd::overlap", kBand}}; }

 private:
  pid_t campaign_;
};

TEST(Campaign, TakesAFindingsSecondOpinionsFromItsWorkerNeverAsksThemItself) {
  CampaignOptions options;
  options.seconds = 1;
  options.seed = 11;
  options.out_of_contract_percent = 0;
  const CampaignResult r = aabb_campaign<CrashesInTheCampaignProcess>(options, ::getpid());
  ASSERT_GT(r.findings.size(), 0u);
  for (const Finding& f : r.findings) {
    EXPECT_TRUE(f.crash.empty()) << f.crash;
    EXPECT_TRUE(disagrees_on(f.input));
    EXPECT_EQ(f.evaluation.verdict.cls, CaseClass::oracle_defect);
    ASSERT_EQ(f.evaluation.opinions.size(), 1u);
    EXPECT_NE(f.evaluation.opinions[0].answer.hit, f.evaluation.library.hit);  // as the worker's answered
  }
}

// Answers like FCL's AABB test, a little slowly (as FCL's managers can be).
class Slow final : public SecondOpinion {
 public:
  std::vector<Opinion> opinions(const Input& in) const override {
    ::usleep(2000);
    return {{"fcl.AABBd::overlap", Opinion::Status::answered, ask_library(in), "", kBand}};
  }
  std::vector<PartyBand> parties(QueryKind) const override { return {{"fcl.AABBd::overlap", kBand}}; }
};

// No limit (a timeout <= 0) is no limit: no case is ever called a hang.
TEST(Campaign, NeverCallsACaseAHangWithoutAPositiveLimit) {
  for (const double timeout : {0.0, -1.0}) {
    CampaignOptions options;
    options.seconds = 0.5;
    options.seed = 13;
    options.out_of_contract_percent = 0;
    options.case_timeout_seconds = timeout;
    const CampaignResult r = aabb_campaign<Slow>(options);
    EXPECT_GT(r.tallies.at(QueryKind::aabb_aabb).cases, 20u);
    for (const Finding& f : r.findings) ADD_FAILURE() << "timeout " << timeout << ": " << f.crash;
  }
}

// The exact reference, crashing on a few inputs in the workers.
class CrashingExact final : public ExactReference {
 public:
  ExactVerdict judge(const Input& in) const override {
    if (crashes_on(in)) std::raise(SIGSEGV);
    return exact_.judge(in);
  }
  Explanation explain(const Input& in) const override { return exact_.explain(in); }
  std::vector<TermError> bound_errors(const bounds::Records& r) const override { return exact_.bound_errors(r); }

 private:
  exact::ExactRationalReference exact_;
};

// A party that crashed answered nothing, and those after it were not asked: the finding says
// the exact verdict was not computed and holds no opinion, instead of a default answer.
TEST(Campaign, InventsNoAnswerForAPartyThatCrashed) {
  CampaignOptions options;
  options.kinds = {QueryKind::aabb_aabb};
  options.workers = 2;
  options.seconds = 2;
  options.seed = 5;
  const Oracles oracles{[] { return std::make_unique<CrashingExact>(); }, [] { return std::make_unique<Unreliable>(); }};
  const CampaignResult r = run_campaign(options, oracles);
  int crashes = 0;
  for (const Finding& f : r.findings) {
    if (f.crash.find("in the exact reference") == std::string::npos) continue;
    ++crashes;
    EXPECT_EQ(f.evaluation.verdict.cls, CaseClass::undecided);
    EXPECT_FALSE(f.evaluation.exact.decided);
    EXPECT_NE(f.evaluation.exact.note.find("killed by signal"), std::string::npos) << f.evaluation.exact.note;
    EXPECT_TRUE(f.evaluation.opinions.empty());
    EXPECT_TRUE(f.evaluation.library_failure.empty());  // the library answered before
  }
  EXPECT_GT(crashes, 0);
}

bool killed_on(const Input& in) { return fingerprint(in) % 1999 == 5; }

// Answers like FCL's AABB test, but on a few inputs another process (a grandchild it starts)
// sends its worker `Signal` (and waits for it): the first time only, or every time. Which cases were hit is kept in
// files of `folder`, which outlive the worker.
template <int Signal, bool EveryTime>
class KilledFromOutside final : public SecondOpinion {
 public:
  explicit KilledFromOutside(std::filesystem::path folder) : folder_(std::move(folder)) {}
  std::vector<Opinion> opinions(const Input& in) const override {
    if (killed_on(in)) {
      const auto mark = folder_ / std::to_string(fingerprint(in));
      const bool first = !std::filesystem::exists(mark);
      std::ofstream(mark, std::ios::app) << "x";
      if (first || EveryTime) {
        if (fork() == 0) {
          kill(getppid(), Signal);
          _exit(0);
        }
        while (interrupts() == 0) pause();  // a fatal signal ends it here; SIGTERM asks it to stop
      }
    }
    return {{"fcl.AABBd::overlap", Opinion::Status::answered, ask_library(in), "", kBand}};
  }
  std::vector<PartyBand> parties(QueryKind) const override { return {{"fcl.AABBd::overlap", kBand}}; }

 private:
  std::filesystem::path folder_;
};

// The number of cases killed at least once, and of kills, as the marks in `folder` tell.
std::pair<int, int> kills_in(const std::filesystem::path& folder) {
  int cases = 0, kills = 0;
  for (const auto& f : std::filesystem::directory_iterator(folder)) {
    ++cases;
    kills += static_cast<int>(std::filesystem::file_size(f.path()));
  }
  return {cases, kills};
}

struct KilledRun {
  CampaignResult result;
  int cases = 0, kills = 0;  // cases killed at least once, and kills
};

// A 2 s aabb_aabb campaign whose workers another process sends `Signal` on a few cases, the
// first time only or every time.
template <int Signal, bool EveryTime>
KilledRun killed_run() {
  const test::TempFolder folder("crosscheck_killed");
  CampaignOptions options;
  options.seconds = 2;
  options.seed = 11;
  options.out_of_contract_percent = 0;
  KilledRun run;
  run.result = aabb_campaign<KilledFromOutside<Signal, EveryTime>>(options, folder.path());
  std::tie(run.cases, run.kills) = kills_in(folder.path());
  return run;
}

template <int Signal>
void check_asked_again_once() {
  const auto [r, cases, kills] = killed_run<Signal, false>();
  ASSERT_GT(cases, 0) << "no case met the kill";
  // Each case killed was asked again and answered: no finding, no case lost.
  EXPECT_TRUE(r.findings.empty()) << r.findings.front().crash;
  // Each case killed is asked again once; the last may have been cut off by the end of the run
  // before it was asked again.
  EXPECT_LE(kills, 2 * cases);
  EXPECT_GE(kills, 2 * cases - 1);
  EXPECT_GE(r.asked_again, static_cast<std::uint64_t>(cases - 1));
  EXPECT_LE(r.asked_again, static_cast<std::uint64_t>(cases));
  EXPECT_EQ(r.tallies.at(QueryKind::aabb_aabb).count(CaseClass::oracle_crash), 0u);
}

TEST(Campaign, AWorkerSentSigsegvByAnotherProcessIsAskedAgainNotBlamed) { check_asked_again_once<SIGSEGV>(); }
TEST(Campaign, AWorkerSentSigkillByAnotherProcessIsAskedAgainNotBlamed) { check_asked_again_once<SIGKILL>(); }

// SIGTERM asks a worker to stop after its case: it answers it, and another worker takes its place.
TEST(Campaign, AWorkerSentSigtermByAnotherProcessIsReplacedAndLosesNothing) {
  const auto [r, cases, kills] = killed_run<SIGTERM, false>();
  ASSERT_GT(cases, 2) << "more workers stopped than the campaign has";
  EXPECT_TRUE(r.findings.empty());
  EXPECT_EQ(r.asked_again, 0u);
  EXPECT_FALSE(r.interrupted);
  EXPECT_GT(r.seconds, 1.9) << "the workers stopped from outside were not replaced";
}

// Killed again when asked again (the kernel's out-of-memory killer would): the case's finding.
TEST(Campaign, ACaseKilledFromOutsideTwiceIsAFinding) {
  const CampaignResult r = killed_run<SIGSEGV, true>().result;
  ASSERT_FALSE(r.findings.empty());
  for (const Finding& f : r.findings) {
    EXPECT_TRUE(killed_on(f.input));
    EXPECT_EQ(f.crash,
              "killed by signal 11 (Segmentation fault), sent by another process, in the case asked again after the same "
              "in the second opinions (FCL/libccd, Bullet, ODE)");
    EXPECT_EQ(f.evaluation.verdict.cls, CaseClass::oracle_crash);
  }
  EXPECT_GE(r.asked_again, r.findings.size());
}

}  // namespace
}  // namespace cc::harness
