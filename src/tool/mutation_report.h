// The outcome of a mutation run: per mutant which check caught it and when, the scores, and the
// Markdown and JSON reports.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tool/mutant_catalogue.h"

namespace cc::tool {

enum class MutantStatus {
  caught_by_ctest,     // a test of one of the ctest labels failed or timed out
  caught_by_campaign,  // ctest passed; the campaign on the mutant's query kind found an impl_bug
  survived,            // every check passed (the campaign may have been unavailable: see note)
  equivalent,          // declared equivalent in the catalogue: not run, left out of the score
  stale,               // its original text is not in the file exactly once: not run
  build_failed,        // the mutated tree does not build: not a valid mutant, left out of the score
  not_executable,      // its code is a SIMD kernel this processor cannot run: not run, left out of the score
  not_run,             // the budget ran out before it could start
  error,               // the runner could not run a check (see note)
};

std::string_view to_string(MutantStatus s);

struct MutantResult {
  Mutant mutant;
  MutantStatus status = MutantStatus::not_run;
  std::string check;           // the ctest label or "campaign" that caught it
  std::string test;            // the failing test, or the campaign's first impl_bug line
  std::string note;            // staleness, build log, campaign unavailable, ...
  double seconds_to_catch = 0;  // from the start of the mutant (build included) to the catch
  double build_seconds = 0;     // incremental builds, all stages
  double seconds = 0;           // the mutant's whole run
  int worker = -1;
  std::string from_run;  // non-empty: carried over from the earlier run of this date (--resume)
};

struct MutationRun {
  std::string date;  // UTC, YYYY-MM-DD HH:MM
  std::string command;
  std::string commit;     // of the source tree ("unknown" outside git; "-dirty" with changes)
  std::string changes;    // with "-dirty": a digest of the uncommitted changes; else empty
  std::string processor;  // its name and hardware threads
  std::string catalogue;
  // The source tree and the work folder as absolute paths: the Markdown report names a file
  // under the first by its path in the repository, under the second as WORK/..., so that a
  // page committed to docs/ names no folder of the machine it ran on.
  std::string source_folder, work_folder;
  int jobs = 1;
  double budget_minutes = 0;
  double campaign_seconds = 0;
  std::uint64_t campaign_seed = 1;
  std::vector<std::string> labels;
  std::vector<std::pair<std::string, double>> baseline;  // label -> seconds of the unmutated tree
  std::vector<std::string> excluded_tests;  // failing on the unmutated tree: left out of the mutant runs
  // A test counted as failed past time_limit_factor times its own time on the unmutated tree,
  // and never before time_limit_floor seconds.
  double time_limit_factor = 5, time_limit_floor = 0;
  double setup_seconds = 0;
  double seconds = 0;
  bool finished = true;      // false in the report written while the run goes on
  std::string resumed_from;  // the report whose results were carried over (--resume), if any
  std::string first_catchers_from;  // the report whose catching tests run first (--first-catchers), if any
  std::vector<MutantResult> results;  // in catalogue order
};

/// Mutants that count (run, built, not equivalent), caught by ctest, and caught by ctest or the
/// campaign.
struct Score {
  int counted = 0, by_ctest = 0, by_either = 0;
};
Score score_of(const MutationRun& run);

/// The layer a mutated file belongs to: "library" (src/collide), "references" (oracle/: the
/// exact reference and the peers), "harness" (src/harness), "tool" (src/tool), or "other".
std::string_view layer_of(std::string_view file);

/// The score of each layer's mutants, in the order library, references, harness, tool, other
/// (layers without mutants left out).
std::vector<std::pair<std::string, Score>> scores_by_layer(const MutationRun& run);

/// The report as Markdown: the scores, then one table row per mutant; paths under
/// run.source_folder and run.work_folder shown relative to them (see MutationRun), and the
/// report it resumed from by its file name.
std::string markdown_report(const MutationRun& run);

/// The report as JSON text.
std::string json_report(const MutationRun& run);

/// Reads a report that json_report wrote (the fields carry_over needs: the run's date, commit,
/// changes, labels and campaign, each mutant's id, file, text and result). Throws
/// std::runtime_error naming the file and the place when it cannot be read or is not one.
MutationRun read_json_report(const std::filesystem::path& path);

/// Takes into `run`, for its mutants still to run, the results of `earlier` that still hold, and returns their indices in
/// run.results. Both runs must be of the same source: the same commit (never "unknown") and the
/// same uncommitted changes, else std::runtime_error says why. A mutant's result is taken when
/// its id, file, original and replacement are the same and it is one of: caught by a check that
/// `run` also runs (a ctest label of its labels, or the campaign with the same seconds and seed);
/// does not build; survived, when `run` runs the same labels and campaign. Anything else (not
/// run, errors, survivors of other checks) is left to run again.
std::vector<std::size_t> carry_over(MutationRun& run, const MutationRun& earlier);

/// The test that caught a mutant in an earlier run, to run first: a failing test is a catch
/// whatever else runs, so a mutant the same test still catches costs that test alone.
struct Catcher {
  std::string label;  // its ctest label (the check that caught it)
  std::string test;   // its ctest name
};

/// The catchers of an earlier run's mutants caught by ctest, by mutant id. The test's name is
/// the report's `test` without the " (how it failed)" that follows it. Any source, any labels:
/// a catcher is only an order to try the tests in.
std::map<std::string, Catcher> catchers_of(const MutationRun& earlier);

}  // namespace cc::tool
