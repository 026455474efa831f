// crosscheck mutate's own scheduling and time limits, on a project of one shell test
// (tests/data/mutate_fixture) and real ctest: each mutant is caught by the test's answer or by
// its time limit, or survives; a mutant is never started past the budget; the source tree is
// left as it was and the scratch tree is reverted.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

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

// crosscheck mutate on the fixture's catalogue, one job, a 2 s floor on test time limits.
MutateRun mutate(const fs::path& scratch, const std::string& budget_minutes) {
  MutateRun r;
  r.outcome = run({kTool, "mutate", "--source", kFixture.string(), "--catalogue", (kFixture / "catalogue.json").string(),
                   "--work", (scratch / "work").string(), "--labels", "unit", "--jobs", "1", "--build-jobs", "1",
                   "--test-timeout", "2", "--campaign-seconds", "0", "--budget", budget_minutes},
                  scratch, scratch);
  if (fs::exists(scratch / "work" / "report.json")) r.report = harness::Json::parse(text_of(scratch / "work" / "report.json"));
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

}  // namespace
}  // namespace cc::test
