// The differential campaign: generated cases of every kind, answered three ways and classified,
// for a time budget. Cases run in forked worker processes, so a crash or a hang inside an
// oracle (or the library) is recorded as a finding and the campaign goes on.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "harness/judging/evaluate.h"

namespace cc::harness {

/// Builds the oracles inside each process that needs them (workers and the supervisor).
struct Oracles {
  std::function<std::unique_ptr<ExactReference>()> exact;
  std::function<std::unique_ptr<SecondOpinion>()> second;
};

struct CampaignOptions {
  std::vector<QueryKind> kinds;
  double seconds = 60;
  std::uint64_t seed = 1;
  int workers = 2;
  double case_timeout_seconds = 20;  // a case running longer is a hang (<= 0: no limit)
  int out_of_contract_percent = 10;  // share of cases generated outside the library's domain
  std::filesystem::path mesh_folder = "corpora/meshes";  // FCL's test meshes, for the mesh queries
  std::function<void(const std::string&)> progress;  // called about once a second
};

struct KindTally {
  std::uint64_t cases = 0;
  std::array<std::uint64_t, std::size(kAllClasses)> by_class{};
  double busy_seconds = 0;  // summed over workers
  std::uint64_t count(CaseClass c) const { return by_class[static_cast<std::size_t>(c)]; }
};

struct Finding {
  QueryKind kind{};
  std::uint64_t case_index = 0;  // with the campaign's seed, regenerates the case
  Input input;
  Evaluation evaluation;
  std::string crash;  // for a worker that died or hung on this case: what and where
  DiedIn died_in = DiedIn::second_opinions;  // where, when `crash` is not empty
};

struct CampaignResult {
  std::uint64_t seed = 0;
  double seconds = 0;
  int workers = 0;  // started (fewer than asked for when a fork failed)
  bool interrupted = false;  // by SIGINT or SIGTERM (see interrupts.h): the workers were stopped
  std::vector<std::string> problems;  // what went wrong in the supervision (a fork that failed)
  std::uint64_t noisy_cases = 0;       // cases on which a party wrote to standard error
  std::uint64_t asked_again = 0;       // cases asked again: their worker was killed from outside
  std::string first_noise;             // the first line one of them wrote, with its case
  std::map<QueryKind, KindTally> tallies;
  /// impl_bug, oracle_defect, oracle_crash and undecided cases, and out_of_contract ones where a
  /// second opinion differs from the exact (or documented) answer
  std::vector<Finding> findings;
};

/// The case with this index in a campaign of this seed, exactly as the campaign generates it.
Input campaign_case(std::uint64_t seed, QueryKind kind, std::uint64_t case_index, int out_of_contract_percent,
                    const std::filesystem::path& mesh_folder = "corpora/meshes");

/// Runs the campaign. SIGINT or SIGTERM (counted from here on: count_interrupts()) stops every
/// worker within a second, keeping every finding reported so far; so does the end of the budget.
/// A worker that cannot be started (fork fails) is a problem of the result, not an abort.
CampaignResult run_campaign(const CampaignOptions& options, const Oracles& oracles);

/// Cases per second for a kind: the rate the whole campaign (all workers) reaches on it.
double cases_per_second(const KindTally& tally, int workers);

}  // namespace cc::harness
