// crosscheck mutate's own scheduling and time limits, on a project of one shell test
// (tests/data/mutate_fixture) and real ctest: each mutant is caught by the test's answer or by
// its time limit, or survives; a mutant is never started past the budget; the source tree is
// left as it was and the scratch tree is reverted.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "cli/program_run.h"
#include "harness/formats/input_json.h"
#include "temp_folder.h"

namespace cc::test {
namespace {

namespace fs = std::filesystem;

const std::string kTool = CROSSCHECK_BINARY;
const fs::path kFixture = fs::path(CROSSCHECK_TEST_DATA) / "mutate_fixture";

struct MutateRun {
  Outcome outcome;
  harness::Json report;  // report.json, null when none was written
};

// crosscheck mutate's command line on the fixture's catalogue: one job, test time limits with a
// floor of `test_timeout` seconds, the work (and the reports) in scratch/`work`.
std::vector<std::string> mutate_argv(const fs::path& scratch, const std::string& budget_minutes,
                                     const std::string& test_timeout = "2", const std::string& work = "work") {
  return {kTool,   "mutate", "--source",     kFixture.string(), "--catalogue", (kFixture / "catalogue.json").string(),
          "--work", (scratch / work).string(), "--labels", "unit", "--jobs", "1", "--build-jobs", "1",
          "--test-timeout", test_timeout, "--campaign-seconds", "0", "--budget", budget_minutes};
}

// The report in scratch/`work`, null when there is none (or it does not parse).
harness::Json report_in(const fs::path& scratch, const std::string& work = "work") {
  const fs::path json = scratch / work / "report.json";
  return fs::exists(json) ? harness::Json::parse(text_of(json), nullptr, false) : harness::Json();
}

MutateRun mutate(const fs::path& scratch, const std::string& budget_minutes) {
  MutateRun r;
  r.outcome = run(mutate_argv(scratch, budget_minutes), scratch, scratch);
  r.report = report_in(scratch);
  return r;
}

const harness::Json& mutant(const harness::Json& report, const std::string& id) {
  for (const harness::Json& m : report["mutants"]) {
    if (m["id"] == id) return m;
  }
  ADD_FAILURE() << "no mutant " << id << " in the report";
  static const harness::Json none = harness::Json::object();
  return none;
}

TEST(MutateRun, EachMutantIsCaughtByItsTestOrByItsTimeLimitOrSurvives) {
  const TempFolder scratch("crosscheck_mutate_run");
  const std::string source_before = text_of(kFixture / "answer.sh");
  // An earlier run's answer of git, left in the work folder, is not taken for this one's.
  fs::create_directories(scratch.path() / "work");
  std::ofstream(scratch.path() / "work" / "commit.log") << "0123456789ab\n";
  const MutateRun r = mutate(scratch.path(), "10");
  EXPECT_EQ(r.outcome.status, 1) << "a mutant survived: " << r.outcome.out << r.outcome.err;
  ASSERT_FALSE(r.report.is_null()) << r.outcome.err;

  const harness::Json& wrong = mutant(r.report, "fixture.wrong_answer");
  EXPECT_EQ(wrong["status"], "caught by ctest");
  EXPECT_EQ(wrong["test"], "answer (Failed)");

  // Cut off at its limit (the 2 s floor: the test takes no time on the unmutated tree), not
  // after the minute it waits, and told as a time-out.
  const harness::Json& hangs = mutant(r.report, "fixture.hangs");
  EXPECT_EQ(hangs["status"], "caught by ctest");
  EXPECT_NE(hangs["test"].get<std::string>().find("answer (Timeout: past"), std::string::npos) << hangs["test"];
  EXPECT_GE(hangs["seconds"].get<double>(), 2.0);
  EXPECT_LT(hangs["seconds"].get<double>(), 30.0);

  EXPECT_EQ(mutant(r.report, "fixture.comment_only")["status"], "SURVIVED");
  // Where it ran: the commit of the fixture's tree (the repository's, outside git "unknown").
  EXPECT_TRUE(std::regex_match(r.report["commit"].get<std::string>(), std::regex("[0-9a-f]{12}(-dirty)?|unknown")))
      << r.report["commit"];
  EXPECT_FALSE(r.report["commit"].get<std::string>().starts_with("0123456789ab")) << r.report["commit"];
  EXPECT_NE(r.report["processor"].get<std::string>().find("hardware threads"), std::string::npos) << r.report["processor"];
  EXPECT_NE(r.outcome.out.find("score: ctest alone 2/3"), std::string::npos) << r.outcome.out;

  // The mutants went into the scratch copy only, and each was taken out again.
  EXPECT_EQ(text_of(kFixture / "answer.sh"), source_before);
  EXPECT_EQ(text_of(scratch.path() / "work" / "worker-0" / "tree" / "answer.sh"), source_before);
}

// Before a mutant starts, its cost is estimated (120 s until one has run): with a budget of a
// minute none starts, and each is reported not run, for that reason.
TEST(MutateRun, NoMutantStartsThatWouldEndPastTheBudget) {
  const TempFolder scratch("crosscheck_mutate_budget");
  const MutateRun r = mutate(scratch.path(), "1");
  ASSERT_FALSE(r.report.is_null()) << r.outcome.err;
  EXPECT_EQ(r.outcome.status, 0) << r.outcome.err;
  for (const harness::Json& m : r.report["mutants"]) {
    EXPECT_EQ(m["status"], "not run") << m["id"];
    EXPECT_EQ(m["note"], "the budget would have been exceeded") << m["id"];
  }
  EXPECT_LT(r.report["seconds"].get<double>(), 60.0);
}

// Kills every process whose command line names `folder` (with its process group): what a run
// killed without warning leaves running.
void kill_processes_under(const fs::path& folder) {
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::string cmdline = text_of(entry.path() / "cmdline");
    std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
    if (cmdline.find(folder.string()) == std::string::npos) continue;
    const pid_t pid = std::stoi(name);
    if (const pid_t group = getpgid(pid); group > 1 && group != getpgrp()) kill(-group, SIGKILL);
    kill(pid, SIGKILL);
  }
}

// The report is written again as each mutant ends, so a run killed without warning (the machine
// goes down) leaves the results it had; --resume takes them and runs only the rest.
TEST(MutateRun, ARunKilledMidwayIsResumedFromItsReport) {
  const TempFolder scratch("crosscheck_mutate_resume");
  // A 30 s floor: fixture.hangs (the second mutant) runs 30 s, time enough to kill the run.
  harness::Child child = harness::start_program(mutate_argv(scratch.path(), "10", "30", "cut"),
                                                {scratch.path(), scratch.path() / "cut.out", scratch.path() / "cut.err"});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(100);
  harness::Json cut;
  while (std::chrono::steady_clock::now() < deadline) {
    cut = report_in(scratch.path(), "cut");
    if (cut.is_object() && mutant(cut, "fixture.wrong_answer")["status"] == "caught by ctest") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  kill(child.pid, SIGKILL);
  harness::finish_child(child);
  kill_processes_under(scratch.path() / "cut");
  ASSERT_TRUE(cut.is_object()) << text_of(scratch.path() / "cut.out") << text_of(scratch.path() / "cut.err");
  EXPECT_EQ(cut["finished"], false);
  EXPECT_EQ(mutant(cut, "fixture.wrong_answer")["status"], "caught by ctest");
  EXPECT_EQ(mutant(cut, "fixture.hangs")["status"], "not run");
  EXPECT_EQ(mutant(cut, "fixture.comment_only")["note"], "not run yet (the run goes on)");

  const std::string earlier = (scratch.path() / "cut" / "report.json").string();
  std::vector<std::string> argv = mutate_argv(scratch.path(), "10", "2", "resumed");
  argv.insert(argv.end(), {"--resume", earlier});
  const Outcome resumed = run(argv, scratch.path(), scratch.path());
  EXPECT_EQ(resumed.status, 1) << "fixture.comment_only survives: " << resumed.out << resumed.err;
  EXPECT_NE(resumed.out.find("1 results carried over, 2 mutants to run"), std::string::npos) << resumed.out;
  const harness::Json report = report_in(scratch.path(), "resumed");
  ASSERT_TRUE(report.is_object()) << resumed.err;
  EXPECT_EQ(report["finished"], true);
  EXPECT_EQ(report["resumed_from"], earlier);
  const harness::Json& carried = mutant(report, "fixture.wrong_answer");
  EXPECT_EQ(carried["status"], "caught by ctest");
  EXPECT_EQ(carried["from_run"], cut["date"]);
  EXPECT_FALSE(fs::exists(scratch.path() / "resumed" / "worker-0" / "logs" / "fixture.wrong_answer.unit.log"))
      << "a carried-over mutant was run again";
  EXPECT_EQ(mutant(report, "fixture.hangs")["status"], "caught by ctest");
  EXPECT_EQ(mutant(report, "fixture.hangs")["from_run"], "");
  EXPECT_EQ(mutant(report, "fixture.comment_only")["status"], "SURVIVED");
  EXPECT_NE(resumed.out.find("score: ctest alone 2/3"), std::string::npos) << resumed.out;
}

// A report of another source is refused before anything is built, naming the flag.
TEST(MutateRun, AReportOfAnotherSourceIsNotResumed) {
  const TempFolder scratch("crosscheck_mutate_resume_other");
  harness::Json other = harness::Json::parse(R"({"date": "2026-11-20 09:00", "commit": "000000000000", "changes": "",
      "labels": ["unit"], "campaign_seconds": 0, "campaign_seed": 1, "mutants": []})");
  std::ofstream(scratch.path() / "other.json") << other.dump();
  std::vector<std::string> argv = mutate_argv(scratch.path(), "10");
  argv.insert(argv.end(), {"--resume", (scratch.path() / "other.json").string()});
  const Outcome o = run(argv, scratch.path(), scratch.path());
  EXPECT_EQ(o.status, 2) << o.out << o.err;
  EXPECT_NE(o.err.find("--resume " + (scratch.path() / "other.json").string() + ": its run was on 000000000000"),
            std::string::npos)
      << o.err;
  EXPECT_FALSE(fs::exists(scratch.path() / "work" / "worker-0")) << "set up before the flag was checked";

  argv.back() = (scratch.path() / "missing.json").string();
  const Outcome missing = run(argv, scratch.path(), scratch.path());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("--resume"), std::string::npos) << missing.err;
}

// --first-catchers: the test that caught a mutant in an earlier run (of any source) runs alone
// first, here answer_again of label property, before label unit's test; a report that cannot be
// read is refused naming the flag, before anything is set up.
TEST(MutateRun, AnEarlierCatcherRunsFirst) {
  const TempFolder scratch("crosscheck_mutate_first_catchers");
  const harness::Json earlier = harness::Json::parse(R"json({"date": "2026-11-20 09:00", "commit": "000000000000",
      "changes": "", "labels": ["property"], "campaign_seconds": 0, "campaign_seed": 1, "mutants": [
      {"id": "fixture.wrong_answer", "query": "aabb_aabb", "file": "answer.sh", "description": "",
       "status": "caught by ctest", "check": "property", "test": "answer_again (Failed)", "note": "",
       "seconds_to_catch": 1, "build_seconds": 0, "seconds": 1, "worker": 0}]})json");
  std::ofstream(scratch.path() / "earlier.json") << earlier.dump();
  std::vector<std::string> argv = mutate_argv(scratch.path(), "10");
  argv[std::find(argv.begin(), argv.end(), "--labels") - argv.begin() + 1] = "unit,property";
  argv.insert(argv.end(), {"--only", "fixture.wrong_answer", "--first-catchers", (scratch.path() / "earlier.json").string()});
  const Outcome o = run(argv, scratch.path(), scratch.path());
  EXPECT_EQ(o.status, 0) << o.out << o.err;
  EXPECT_NE(o.out.find("1 mutants' earlier catching tests run first"), std::string::npos) << o.out;
  const harness::Json report = report_in(scratch.path());
  ASSERT_TRUE(report.is_object()) << o.err;
  const harness::Json& caught = mutant(report, "fixture.wrong_answer");
  EXPECT_EQ(caught["status"], "caught by ctest");
  EXPECT_EQ(caught["check"], "property");
  EXPECT_EQ(caught["test"], "answer_again (Failed)");
  const fs::path logs = scratch.path() / "work" / "worker-0" / "logs";
  EXPECT_TRUE(fs::exists(logs / "fixture.wrong_answer.first.log"));
  EXPECT_FALSE(fs::exists(logs / "fixture.wrong_answer.unit.log")) << "label unit ran before the earlier catcher";
  EXPECT_EQ(report["first_catchers_from"], (scratch.path() / "earlier.json").string());

  std::ofstream(scratch.path() / "broken.json") << R"({"date": "2026-11-20 09:00"})";
  argv.back() = (scratch.path() / "broken.json").string();
  argv[std::find(argv.begin(), argv.end(), "--work") - argv.begin() + 1] = (scratch.path() / "refused").string();
  const Outcome refused = run(argv, scratch.path(), scratch.path());
  EXPECT_EQ(refused.status, 2) << refused.out << refused.err;
  EXPECT_NE(refused.err.find("--first-catchers " + argv.back() + ": "), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(scratch.path() / "refused" / "worker-0")) << "set up before the flag was checked";
}

// SIGTERM while the scratch trees are set up kills their build: the run says it was interrupted,
// not that the tree does not build.
TEST(MutateRun, AnInterruptDuringSetUpIsToldAsOne) {
  const TempFolder scratch("crosscheck_mutate_setup_interrupt");
  const fs::path out = scratch.path() / "out", err = scratch.path() / "err";
  const harness::ChildEnd end =
      harness::run_program(mutate_argv(scratch.path(), "10"), {scratch.path(), out, err}, 120,
                           [&] { return fs::exists(scratch.path() / "work" / "worker-0" / "logs"); });
  EXPECT_EQ(end.signal, 0) << "it ends by itself, after killing its children";
  EXPECT_EQ(end.status, 1) << text_of(err);
  EXPECT_NE(text_of(err).find("interrupted (SIGINT or SIGTERM) while setting up"), std::string::npos) << text_of(err);
  EXPECT_EQ(text_of(err).find("failed"), std::string::npos) << text_of(err);
}

}  // namespace
}  // namespace cc::test
