// The outcome of a mutation run: the score counts only the mutants that ran and built and are
// not equivalent, ctest alone apart from ctest plus the campaign; the Markdown and JSON reports
// carry those figures and one entry per mutant.
#include "tool/mutation_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "temp_folder.h"

namespace cc::tool {
namespace {

MutantResult result(const std::string& id, MutantStatus status) {
  MutantResult r;
  r.mutant.id = id;
  r.mutant.query = "ray_aabb";
  r.mutant.file = "src/collide/ray_aabb.cpp";
  r.mutant.description = "the bug of " + id;
  r.status = status;
  return r;
}

MutantResult caught(const std::string& id, MutantStatus status, const std::string& check, const std::string& test,
                    double seconds) {
  MutantResult r = result(id, status);
  r.check = check;
  r.test = test;
  r.seconds_to_catch = seconds;
  return r;
}

// Two caught by ctest, one by the campaign, one survivor, and one of each kind left out.
MutationRun sample_run() {
  MutationRun run;
  run.date = "2026-11-21 10:00";
  run.command = "crosscheck mutate --jobs 2";
  run.commit = "0123456789ab-dirty";
  run.processor = "Some CPU, 2 hardware threads";
  run.catalogue = "tests/mutation/mutants.json";
  run.jobs = 2;
  run.budget_minutes = 60;
  run.campaign_seconds = 60;
  run.labels = {"corpus", "fuzz", "unit", "property"};
  run.baseline = {{"unit", 42}, {"property", 300}};
  run.excluded_tests = {"Broken.Test"};
  run.time_limit_floor = 10;

  MutantResult equivalent = result("e.equivalent", MutantStatus::equivalent);
  equivalent.mutant.equivalent = "both branches give the same double";
  MutantResult stale = result("f.stale", MutantStatus::stale);
  stale.note = "the original text is not found in src/collide/ray_aabb.cpp";
  MutantResult not_building = result("g.not_building", MutantStatus::build_failed);
  not_building.note = "see build.log | with a pipe\nand a newline";
  run.results = {caught("a.by_unit", MutantStatus::caught_by_ctest, "unit", "RayAabb.Grazes (Failed)", 73),
                 caught("b.by_property", MutantStatus::caught_by_ctest, "property",
                        "Differential.TheLibraryIsNeverAnImplBug/ray_aabb (Failed)", 210),
                 caught("c.by_campaign", MutantStatus::caught_by_campaign, "campaign",
                        "impl_bug ray_aabb seed 1 case 77", 400),
                 result("d.survivor", MutantStatus::survived),
                 equivalent,
                 stale,
                 not_building,
                 result("h.not_run", MutantStatus::not_run),
                 result("i.error", MutantStatus::error),
                 result("j.avx512_only", MutantStatus::not_executable)};
  run.results.back().note = "its code is the avx512 kernel, and this processor lacks AVX-512 F, DQ and VL";
  run.results.back().mutant.description = "`|x| < 1` for `|x| <= 1` in the avx512 kernel";
  return run;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(MutationReport, TheScoreCountsOnlyMutantsThatRanBuiltAndAreNotEquivalent) {
  const Score s = score_of(sample_run());
  EXPECT_EQ(s.counted, 4);    // two by ctest, one by the campaign, one survivor
  EXPECT_EQ(s.by_ctest, 2);   // the campaign's catch is not ctest's
  EXPECT_EQ(s.by_either, 3);  // the survivor is in neither
}

TEST(MutationReport, AnEmptyRunScoresNothing) {
  const Score s = score_of(MutationRun{});
  EXPECT_EQ(s.counted, 0);
  EXPECT_EQ(s.by_ctest, 0);
  EXPECT_EQ(s.by_either, 0);
  EXPECT_TRUE(contains(markdown_report(MutationRun{}), "| ctest alone | 0 | 0 | - |"));
}

TEST(MutationReport, EveryStatusHasItsOwnName) {
  std::set<std::string> names;
  for (MutantStatus s : {MutantStatus::caught_by_ctest, MutantStatus::caught_by_campaign, MutantStatus::survived,
                         MutantStatus::equivalent, MutantStatus::stale, MutantStatus::build_failed,
                         MutantStatus::not_run, MutantStatus::error, MutantStatus::not_executable}) {
    names.insert(std::string(to_string(s)));
  }
  EXPECT_EQ(names.size(), 9u);
}

TEST(MutationReport, MarkdownAndJsonSayWhenWhereAndHowTheyWereMade) {
  const std::string md = markdown_report(sample_run());
  EXPECT_TRUE(contains(md, "- date: 2026-11-21 10:00 UTC\n- commit: 0123456789ab-dirty\n"
                           "- processor: Some CPU, 2 hardware threads\n- command: `crosscheck mutate --jobs 2`\n"))
      << md;
  const auto j = nlohmann::json::parse(json_report(sample_run()));
  EXPECT_EQ(j["commit"], "0123456789ab-dirty");
  EXPECT_EQ(j["processor"], "Some CPU, 2 hardware threads");
}

TEST(MutationReport, MarkdownHasTheScoresAndWhatWasLeftOut) {
  const std::string md = markdown_report(sample_run());
  EXPECT_TRUE(contains(md, "| ctest alone | 2 | 4 | 50.0% |")) << md;
  EXPECT_TRUE(contains(md, "| ctest + campaign | 3 | 4 | 75.0% |")) << md;
  EXPECT_TRUE(contains(md, "1 equivalent, 1 stale, 1 not building, 1 not run (budget or interrupted), 1 runner errors, "
                           "1 not executable here"))
      << md;
  EXPECT_TRUE(contains(md, "past 5 times its own time on the unmutated tree, and at least 10 s")) << md;
  EXPECT_TRUE(contains(md, "corpus, fuzz, unit, property")) << md;
  EXPECT_TRUE(contains(md, "unit 42 s; property 300 s;")) << md;
  EXPECT_TRUE(contains(md, "`Broken.Test`")) << md;
}

TEST(MutationReport, MarkdownHasOneRowPerMutantWithWhatCaughtItAndWhen) {
  const MutationRun run = sample_run();
  const std::string md = markdown_report(run);
  for (const MutantResult& r : run.results) EXPECT_TRUE(contains(md, "| `" + r.mutant.id + "` |")) << r.mutant.id;
  EXPECT_TRUE(contains(md, "| caught by ctest | unit: RayAabb.Grazes (Failed) | 73 s |")) << md;
  EXPECT_TRUE(contains(md, "| caught by campaign | campaign: impl_bug ray_aabb seed 1 case 77 | 400 s |")) << md;
  EXPECT_TRUE(contains(md, "both branches give the same double")) << md;  // why equivalent
  EXPECT_TRUE(contains(md, "the bug of d.survivor")) << md;               // a survivor's description
}

// The row of a mutant in the Markdown report, and its columns (split at unescaped pipes).
std::vector<std::string> columns_of(const std::string& md, const std::string& id) {
  const auto at = md.find("| `" + id + "` |");
  if (at == std::string::npos) return {};
  const std::string row = md.substr(at, md.find('\n', at) - at);
  std::vector<std::string> out;
  std::string current;
  for (std::size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '|' && row[i - 1] != '\\') {
      out.push_back(current);
      current.clear();
    } else {
      current += row[i];
    }
  }
  return out;
}

TEST(MutationReport, MarkdownCellsEscapePipesAndHoldNoNewline) {
  const std::string md = markdown_report(sample_run());
  const std::vector<std::string> cells = columns_of(md, "g.not_building");
  ASSERT_EQ(cells.size(), 8u) << md;  // eight columns
  EXPECT_EQ(cells[7], " see build.log \\| with a pipe and a newline ") << md;
  EXPECT_EQ(columns_of(md, "j.avx512_only").size(), 8u) << md;
}

TEST(MutationReport, AMutantOfAKernelThisProcessorLacksIsSaidSo) {
  const std::string md = markdown_report(sample_run());
  const std::vector<std::string> cells = columns_of(md, "j.avx512_only");
  ASSERT_EQ(cells.size(), 8u) << md;
  EXPECT_EQ(cells[3], " not executable here ");
  EXPECT_TRUE(contains(cells[7], "this processor lacks AVX-512 F, DQ and VL")) << cells[7];
  EXPECT_EQ(score_of(sample_run()).counted, 4);  // not a survivor: left out of the score
}

TEST(MutationReport, JsonHasTheScoresAndEveryMutant) {
  const MutationRun run = sample_run();
  const auto j = nlohmann::json::parse(json_report(run));
  EXPECT_EQ(j["score"]["counted"], 4);
  EXPECT_EQ(j["score"]["caught_by_ctest"], 2);
  EXPECT_EQ(j["score"]["caught_by_ctest_or_campaign"], 3);
  EXPECT_DOUBLE_EQ(j["score"]["ctest_fraction"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(j["score"]["ctest_or_campaign_fraction"].get<double>(), 0.75);
  EXPECT_EQ(j["catalogue"], "tests/mutation/mutants.json");
  EXPECT_EQ(j["baseline_seconds"]["property"], 300);
  EXPECT_EQ(j["excluded_tests"], nlohmann::json::array({"Broken.Test"}));
  ASSERT_EQ(j["mutants"].size(), run.results.size());
  const auto& by_property = j["mutants"][1];
  EXPECT_EQ(by_property["id"], "b.by_property");
  EXPECT_EQ(by_property["status"], "caught by ctest");
  EXPECT_EQ(by_property["check"], "property");
  EXPECT_EQ(by_property["seconds_to_catch"], 210);
  EXPECT_EQ(j["mutants"][4]["status"], "equivalent");
  EXPECT_EQ(j["mutants"][4]["note"], "both branches give the same double");
  EXPECT_EQ(j["mutants"][5]["status"], "STALE");
  EXPECT_EQ(j["mutants"][5]["note"], "the original text is not found in src/collide/ray_aabb.cpp");
}

TEST(MutationReport, JsonOfAnEmptyRunHasZeroFractions) {
  const auto j = nlohmann::json::parse(json_report(MutationRun{}));
  EXPECT_EQ(j["score"]["counted"], 0);
  EXPECT_EQ(j["score"]["ctest_fraction"], 0.0);
  EXPECT_TRUE(j["mutants"].empty());
}

// The score of each layer, told from the mutated file's folder.
TEST(MutationReport, EachLayerHasItsOwnScore) {
  EXPECT_EQ(layer_of("src/collide/obb.cpp"), "library");
  EXPECT_EQ(layer_of("oracle/exact/rational.cpp"), "references");
  EXPECT_EQ(layer_of("oracle/fcl/fcl_shapes.cpp"), "references");
  EXPECT_EQ(layer_of("src/harness/processes/child.cpp"), "harness");
  EXPECT_EQ(layer_of("src/tool/flag_checks.cpp"), "tool");
  EXPECT_EQ(layer_of("fuzz/mutator.cpp"), "other");
  MutationRun run = sample_run();  // its mutants are the library's
  MutantResult tool = caught("k.tool", MutantStatus::caught_by_ctest, "unit", "FlagRanges.X (Failed)", 5);
  tool.mutant.file = "src/tool/flag_checks.cpp";
  MutantResult harness = result("l.harness", MutantStatus::survived);
  harness.mutant.file = "src/harness/shrinking/shrink.cpp";
  MutantResult equivalent_reference = result("m.reference", MutantStatus::equivalent);
  equivalent_reference.mutant.file = "oracle/exact/rational.cpp";
  run.results.insert(run.results.end(), {tool, harness, equivalent_reference});
  const auto layers = scores_by_layer(run);
  ASSERT_EQ(layers.size(), 4u);
  EXPECT_EQ(layers[0].first, "library");
  EXPECT_EQ(layers[0].second.counted, 4);
  EXPECT_EQ(layers[0].second.by_ctest, 2);
  EXPECT_EQ(layers[0].second.by_either, 3);
  EXPECT_EQ(layers[1].first, "references");
  EXPECT_EQ(layers[1].second.counted, 0);  // an equivalent mutant alone: listed, scores nothing
  EXPECT_EQ(layers[2].first, "harness");
  EXPECT_EQ(layers[2].second.counted, 1);
  EXPECT_EQ(layers[2].second.by_ctest, 0);
  EXPECT_EQ(layers[3].first, "tool");
  EXPECT_EQ(layers[3].second.by_ctest, 1);
  const std::string md = markdown_report(run);
  EXPECT_TRUE(contains(md, "| library | 2 (50.0%) | 3 (75.0%) | 4 |")) << md;
  EXPECT_TRUE(contains(md, "| tool | 1 (100.0%) | 1 (100.0%) | 1 |")) << md;
  const auto j = nlohmann::json::parse(json_report(run));
  EXPECT_EQ(j["score_by_layer"]["harness"]["counted"], 1);
  EXPECT_EQ(j["score_by_layer"]["tool"]["caught_by_ctest"], 1);
}

// Resuming: a report read back holds what carry_over needs, as written.
TEST(MutationReport, TheCatchersAreTheTestsThatCaughtMutantsByCtest) {
  MutationRun run;
  run.results = {caught("a", MutantStatus::caught_by_ctest, "unit", "Suite.Test (Failed)", 3),
                 caught("b", MutantStatus::caught_by_ctest, "property", "Prop/x (Timeout: past 50 s (5 x 10 s))", 60),
                 caught("c", MutantStatus::caught_by_campaign, "campaign", "impl_bug ray_aabb ...", 70),
                 result("d", MutantStatus::survived)};
  const auto catchers = catchers_of(run);
  ASSERT_EQ(catchers.size(), 2u);
  EXPECT_EQ(catchers.at("a").label, "unit");
  EXPECT_EQ(catchers.at("a").test, "Suite.Test");
  EXPECT_EQ(catchers.at("b").label, "property");
  EXPECT_EQ(catchers.at("b").test, "Prop/x");
}

TEST(MutationReport, AJsonReportReadsBackAsWritten) {
  MutationRun run = sample_run();
  run.changes = "changes 00000000000000ff";
  run.results[0].mutant.original = "t < 1";
  run.results[0].mutant.replacement = "t <= 1";
  run.results[0].from_run = "2026-11-20 09:00";
  const test::TempFolder scratch("crosscheck_mutation_report");
  const auto path = scratch.path() / "report.json";
  std::ofstream(path) << json_report(run);
  const MutationRun back = read_json_report(path);
  EXPECT_EQ(back.date, run.date);
  EXPECT_EQ(back.commit, run.commit);
  EXPECT_EQ(back.changes, run.changes);
  EXPECT_EQ(back.labels, run.labels);
  EXPECT_EQ(back.campaign_seconds, run.campaign_seconds);
  ASSERT_EQ(back.results.size(), run.results.size());
  for (std::size_t i = 0; i < run.results.size(); ++i) {
    const MutantResult &a = back.results[i], &b = run.results[i];
    EXPECT_EQ(a.mutant.id, b.mutant.id);
    EXPECT_EQ(a.mutant.file, b.mutant.file);
    EXPECT_EQ(a.status, b.status) << b.mutant.id;
    EXPECT_EQ(a.check, b.check);
    EXPECT_EQ(a.test, b.test);
    EXPECT_EQ(a.seconds_to_catch, b.seconds_to_catch);
  }
  EXPECT_EQ(back.results[0].mutant.original, "t < 1");
  EXPECT_EQ(back.results[0].mutant.replacement, "t <= 1");
  EXPECT_EQ(back.results[0].from_run, "2026-11-20 09:00");
}

TEST(MutationReport, ABadReportIsRefusedNamingTheFileAndThePlace) {
  const test::TempFolder scratch("crosscheck_mutation_report_bad");
  const auto path = scratch.path() / "report.json";
  auto j = nlohmann::json::parse(json_report(sample_run()));
  j["mutants"][2]["status"] = "caught by luck";
  std::ofstream(path) << j.dump();
  try {
    read_json_report(path);
    ADD_FAILURE() << "read";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(contains(e.what(), path.string() + ": /mutants/2/status")) << e.what();
  }
  j = nlohmann::json::parse(json_report(sample_run()));
  j["mutants"][1].erase("check");
  std::ofstream(path, std::ios::trunc) << j.dump();
  EXPECT_THROW(read_json_report(path), std::runtime_error);
  std::ofstream(path, std::ios::trunc) << "{\"date\": ";
  EXPECT_THROW(read_json_report(path), std::runtime_error);
}

// The runs to resume: an earlier one on commit 0123456789ab (clean) with each kind of result,
// and the same catalogue to run now, every mutant still to run.
MutationRun earlier_run() {
  MutationRun run = sample_run();
  run.commit = "0123456789ab";
  return run;
}

MutationRun run_to_resume(const std::vector<std::string>& labels) {
  MutationRun run = earlier_run();
  run.date = "2026-11-22 08:00";
  run.labels = labels;
  for (MutantResult& r : run.results) {
    r.status = MutantStatus::not_run;
    r.check.clear(), r.test.clear(), r.note.clear();
    r.seconds_to_catch = 0;
  }
  return run;
}

MutantStatus status_of(const MutationRun& run, const std::string& id) {
  for (const MutantResult& r : run.results) {
    if (r.mutant.id == id) return r.status;
  }
  ADD_FAILURE() << "no mutant " << id;
  return MutantStatus::error;
}

TEST(MutationReport, ResumingTakesWhatStillHoldsAndLeavesTheRestToRun) {
  MutationRun now = run_to_resume(earlier_run().labels);
  const std::vector<std::size_t> carried = carry_over(now, earlier_run());
  // Caught by ctest twice, by the campaign (same seconds and seed), a survivor (same checks),
  // one that does not build; not the stale, not-run, error or equivalent ones.
  EXPECT_EQ(carried, (std::vector<std::size_t>{0, 1, 2, 3, 6}));
  EXPECT_EQ(status_of(now, "a.by_unit"), MutantStatus::caught_by_ctest);
  EXPECT_EQ(now.results[0].test, "RayAabb.Grazes (Failed)");
  EXPECT_EQ(now.results[0].seconds_to_catch, 73);
  EXPECT_EQ(now.results[0].from_run, "2026-11-21 10:00");
  EXPECT_EQ(status_of(now, "h.not_run"), MutantStatus::not_run);
  EXPECT_EQ(status_of(now, "i.error"), MutantStatus::not_run);
  EXPECT_TRUE(contains(markdown_report(now), "(from the run of 2026-11-21 10:00)"));
}

TEST(MutationReport, ACatchIsTakenOnlyWhenThisRunHasItsCheck) {
  // Without the property label the property catch must be found again, and with other labels a
  // survivor may now be caught.
  MutationRun now = run_to_resume({"corpus", "unit"});
  carry_over(now, earlier_run());
  EXPECT_EQ(status_of(now, "a.by_unit"), MutantStatus::caught_by_ctest);
  EXPECT_EQ(status_of(now, "b.by_property"), MutantStatus::not_run);
  EXPECT_EQ(status_of(now, "d.survivor"), MutantStatus::not_run);
  EXPECT_EQ(status_of(now, "c.by_campaign"), MutantStatus::caught_by_campaign);
  // Another campaign seed: its catch is not this run's.
  now = run_to_resume({"corpus", "unit"});
  now.campaign_seed = 2;
  carry_over(now, earlier_run());
  EXPECT_EQ(status_of(now, "c.by_campaign"), MutantStatus::not_run);
}

TEST(MutationReport, AMutantWhoseTextChangedRunsAgain) {
  MutationRun now = run_to_resume(earlier_run().labels);
  now.results[0].mutant.replacement = "something else";
  now.results[1].mutant.file = "src/collide/other.cpp";
  carry_over(now, earlier_run());
  EXPECT_EQ(status_of(now, "a.by_unit"), MutantStatus::not_run);
  EXPECT_EQ(status_of(now, "b.by_property"), MutantStatus::not_run);
}

TEST(MutationReport, OnlyARunOnTheSameSourceIsResumed) {
  MutationRun now = run_to_resume(earlier_run().labels);
  now.commit = "ba9876543210";
  EXPECT_THROW(carry_over(now, earlier_run()), std::runtime_error);
  now.commit = "0123456789ab-dirty";  // the same commit with changes
  now.changes = "changes 0000000000000001";
  EXPECT_THROW(carry_over(now, earlier_run()), std::runtime_error);
  MutationRun earlier = earlier_run();
  earlier.commit = now.commit;
  earlier.changes = "changes 0000000000000002";  // other changes
  EXPECT_THROW(carry_over(now, earlier), std::runtime_error);
  earlier.changes = now.changes;
  EXPECT_NO_THROW(carry_over(now, earlier));
  now.commit = earlier.commit = "unknown";
  now.changes = earlier.changes = "";
  now.results = run_to_resume(earlier_run().labels).results;
  EXPECT_THROW(carry_over(now, earlier), std::runtime_error);
  EXPECT_EQ(status_of(now, "a.by_unit"), MutantStatus::not_run);
}

TEST(MutationReport, AnUnfinishedReportSaysSo) {
  MutationRun run = sample_run();
  run.finished = false;
  run.resumed_from = "build/mutate/report.json";
  run.results[0].from_run = "2026-11-20 09:00";
  const std::string md = markdown_report(run);
  EXPECT_TRUE(contains(md, "**Unfinished**")) << md;
  EXPECT_TRUE(contains(md, "- resumed from: `build/mutate/report.json`, whose results for 1 mutants")) << md;
  EXPECT_EQ(nlohmann::json::parse(json_report(run))["finished"], false);
  EXPECT_FALSE(contains(markdown_report(sample_run()), "Unfinished"));
}

// A page committed to docs/ names no folder of the machine: the catalogue by its path in the
// repository, the logs under the work folder as WORK/...; the JSON keeps the paths whole.
TEST(MutationReport, MarkdownNamesNoFolderOfTheMachine) {
  MutationRun run = sample_run();
  run.source_folder = "/home/someone/tree";
  run.work_folder = "/scratch/mutate/";
  run.catalogue = "/home/someone/tree/tests/mutation/mutants.json";
  run.command = "crosscheck mutate --catalogue /home/someone/tree/tests/mutation/mutants.json --jobs 2";
  run.results[6].note = "see /scratch/mutate/worker-0/logs/g.build.log and /scratch/mutate/worker-1/logs/g.build.log";
  const std::string md = markdown_report(run);
  EXPECT_TRUE(contains(md, "Catalogue `tests/mutation/mutants.json`")) << md;
  EXPECT_TRUE(contains(md, "- command: `crosscheck mutate --catalogue tests/mutation/mutants.json --jobs 2`")) << md;
  EXPECT_TRUE(contains(md, "see WORK/worker-0/logs/g.build.log and WORK/worker-1/logs/g.build.log")) << md;
  EXPECT_FALSE(contains(md, "/home/someone")) << md;
  EXPECT_FALSE(contains(md, "/scratch")) << md;
  EXPECT_TRUE(contains(json_report(run), "/home/someone/tree/tests/mutation/mutants.json"));
  run.resumed_from = "/elsewhere/earlier.json";
  run.command += " --resume /elsewhere/earlier.json";
  const std::string resumed = markdown_report(run);
  EXPECT_TRUE(contains(resumed, "--jobs 2 --resume earlier.json`")) << resumed;
  EXPECT_TRUE(contains(resumed, "- resumed from: `earlier.json`")) << resumed;
  EXPECT_FALSE(contains(resumed, "/elsewhere")) << resumed;
}

}  // namespace
}  // namespace cc::tool
