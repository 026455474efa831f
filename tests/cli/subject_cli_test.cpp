// A user's library under test, as a user runs the tool (label cli): each hostile subject built
// by the tests (tests/subjects/hostile.cpp) leaves the campaign going to its time, its findings
// stored with the subject recorded, exit 1, and nothing of its printing on the terminal; one
// whose loading crashes, exits or hangs ends the command with exit 2 and one line naming the
// file. A subject's finding takes --max-new before other parties' cases; its case is never
// answered by crosscheck's own library (triage, shrink and replay without --subject exit 2; the
// environment variable gives the subject), and replayed with the same answers it is unchanged.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/program_run.h"
#include "harness/formats/case_file.h"
#include "temp_folder.h"

namespace cc::test {
namespace {

namespace fs = std::filesystem;

std::string subject(const std::string& fault) {
  return std::string(CROSSCHECK_SUBJECTS_DIR) + "/libtest_subject_hostile_" + fault + ".so";
}

// `crosscheck args...` from the source tree, its output and error kept apart.
Outcome crosscheck(const std::vector<std::string>& args, const fs::path& folder) {
  std::vector<std::string> argv = {CROSSCHECK_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  return run(argv, CROSSCHECK_SOURCE_DIR, folder);
}

std::vector<fs::path> case_files(const fs::path& folder) {
  std::vector<fs::path> files;
  if (!fs::exists(folder)) return files;
  for (const auto& e : fs::recursive_directory_iterator(folder)) {
    if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
  }
  return files;
}

// A short campaign of aabb_aabb with the subject, into folder/found (no corpus to skip).
Outcome campaign(const std::string& path, const fs::path& folder, std::vector<std::string> more = {}) {
  fs::create_directories(folder / "no_corpus");
  std::vector<std::string> args = {"campaign", "--subject", path, "--query", "aabb_aabb", "--workers", "2",
                                   "--timeout", "2", "--out", (folder / "found").string(),
                                   "--corpora", (folder / "no_corpus").string()};
  args.insert(args.end(), more.begin(), more.end());
  return crosscheck(args, folder);
}

TEST(SubjectCli, EachHostileSubjectLeavesTheRunGoingAndItsFindingsStored) {
  const std::pair<std::string, std::string> faults[] = {
      {"exits", "exited with status 0"},
      {"exits_nonzero", "exited with status 3"},
      {"aborts", "was killed by signal 6 (Aborted)"},
      {"prints", "wrote to standard output"},
      {"closes_fds", "closed file descriptor 3"},
      {"writes_fds", "wrote to file descriptor 4"},
  };
  for (const auto& [fault, what] : faults) {
    const TempFolder folder("crosscheck_subject_" + fault);
    const Outcome r = campaign(subject(fault), folder.path(), {"--seconds", "3", "--max-new", "2", "--json",
                                                            (folder.path() / "run.json").string()});
    EXPECT_EQ(r.status, 1) << fault << "\n" << r.out << r.err;
    const harness::Json json = harness::Json::parse(text_of(folder.path() / "run.json"));
    EXPECT_GT(json["seconds"].get<double>(), 1.5) << fault;  // its share of the 3 s: it ran to its time
    EXPECT_GT(json["queries"]["aabb_aabb"]["impl_bug"].get<int>(), 10) << fault;
    const auto files = case_files(folder.path() / "found");
    ASSERT_FALSE(files.empty()) << fault << "\n" << r.out << r.err;
    for (const fs::path& file : files) {
      const harness::Case c = harness::read_case_file(file);
      EXPECT_EQ(c.cls, harness::CaseClass::impl_bug) << file;
      EXPECT_NE(c.library_failure.find(what), std::string::npos) << fault << ": " << c.library_failure;
      ASSERT_TRUE(c.subject.has_value()) << file;
      EXPECT_EQ(c.subject->file, "libtest_subject_hostile_" + fault + ".so");
      EXPECT_EQ(c.subject->sha256.size(), 64u);
      EXPECT_EQ(c.subject->kinds, std::vector<std::string>{"aabb_aabb"});
    }
    // Quoted in a finding's line or the summary's, never printed raw on every call.
    std::size_t quoted = 0;
    for (std::size_t at = r.out.find("checking boxes"); at != std::string::npos; at = r.out.find("checking boxes", at + 1)) {
      ++quoted;
    }
    EXPECT_LT(quoted, 5u) << "the subject's printing reached the terminal:\n" << r.out;
    EXPECT_EQ(r.err.find("aabb_aabb called"), std::string::npos) << "the subject's printing reached the terminal";
    if (fault == "prints") {
      EXPECT_NE(r.out.find("cases wrote to standard output or error"), std::string::npos) << r.out;
    }
  }
}

TEST(SubjectCli, ASubjectWhoseLoadingFailsEndsTheCommandWithOneLine) {
  const TempFolder folder("crosscheck_subject_load");
  for (const auto& [fault, what] : {std::pair<std::string, std::string>{"load_aborts", "killed by signal 6 (Aborted)"},
                                    {"load_exits", "exited with status 0"}}) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"campaign", "--subject", subject(fault), "--seconds", "5"},
          std::vector<std::string>{"replay", "--subject", subject(fault), "corpora/aabb_aabb"}}) {
      const Outcome r = crosscheck(args, folder.path());
      EXPECT_EQ(r.status, 2) << fault << r.out << r.err;
      // One line naming the file and what happened; then the tool's usual hint for a bad flag.
      const std::string first = r.err.substr(0, r.err.find('\n'));
      EXPECT_EQ(first.find("--subject: " + subject(fault) + ": " + what + " while being loaded"), 0u) << r.err;
      EXPECT_EQ(r.err.substr(first.size()), "\nRun with --help for more information.\n") << r.err;
    }
  }
}

TEST(SubjectCli, TheSubjectsFindingsComeFirstAndItsCasesAreNeverAnsweredByAnotherLibrary) {
  const TempFolder folder("crosscheck_subject_first");
  const std::string wrong = subject("wrong");
  // Out of contract, FCL's answers differ from the documented ones on most cases: in turns with
  // the subject's, they would take one of the two places of --max-new.
  const Outcome r = campaign(wrong, folder.path(), {"--seconds", "6", "--max-new", "2", "--per-kind-of-finding", "100",
                                                "--out-of-contract", "60", "--json", (folder.path() / "run.json").string()});
  ASSERT_EQ(r.status, 1) << r.out << r.err;
  const harness::Json json = harness::Json::parse(text_of(folder.path() / "run.json"));
  int over_cap_others = 0;
  for (const harness::Json& f : json["findings"]) {
    if (f["stored"] == "written") {
      EXPECT_EQ(f["class"], "impl_bug") << f.dump();
    }
    over_cap_others += f["stored"] == "not stored (--max-new)" && f["class"] != "impl_bug";
  }
  EXPECT_GT(over_cap_others, 0) << "no other party's finding competed for --max-new";
  EXPECT_NE(r.out.find("go to the library's findings, impl_bug: the subject's, before"), std::string::npos) << r.out;
  const auto files = case_files(folder.path() / "found");  // two, or one they both shrank to
  ASSERT_FALSE(files.empty());
  const std::string file = files.front().string();

  for (const char* command : {"triage", "shrink", "replay"}) {
    const Outcome alone = crosscheck({command, file}, folder.path());
    EXPECT_EQ(alone.status, 2) << command << alone.out << alone.err;
    EXPECT_NE(alone.err.find("found with the subject libtest_subject_hostile_wrong.so"), std::string::npos) << alone.err;
    EXPECT_EQ(alone.out.find("agree"), std::string::npos) << command << " answered with another library:\n" << alone.out;
  }
  const Outcome triage = crosscheck({"triage", "--subject", wrong, file}, folder.path());
  EXPECT_EQ(triage.status, 0) << triage.out << triage.err;
  EXPECT_NE(triage.out.find("class      impl_bug"), std::string::npos) << triage.out;
  EXPECT_EQ(triage.out.find("recorded:"), std::string::npos) << "the class changed:\n" << triage.out;

  const Outcome replay = crosscheck({"replay", "--subject", wrong, (folder.path() / "found").string()}, folder.path());
  EXPECT_EQ(replay.status, 0) << replay.out << replay.err;
  const std::string n = std::to_string(files.size());
  EXPECT_NE(replay.out.find(n + " cases replayed: " + n + " unchanged, 0 changed"), std::string::npos) << replay.out;

  ::setenv("CROSSCHECK_SUBJECT", wrong.c_str(), 1);
  const Outcome from_environment = crosscheck({"replay", file}, folder.path());
  ::unsetenv("CROSSCHECK_SUBJECT");
  EXPECT_EQ(from_environment.status, 0) << from_environment.out << from_environment.err;

  // Another build of the subject: asked, and said so.
  const Outcome other = crosscheck({"triage", "--subject", subject("exits"), file}, folder.path());
  EXPECT_NE(other.err.find("found with libtest_subject_hostile_wrong.so"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("asking libtest_subject_hostile_exits.so"), std::string::npos) << other.err;
}

// A worker answers in a process with a history, replay in a fresh one: a subject whose answers
// depend on what its process did before (right on its first 100 calls, touching boxes a miss
// after) is wrong in the workers, right in a fresh process. Its findings are stored with the
// fresh process's answers, the worker's in the note, so each replays unchanged, even after
// a hundred others.
TEST(SubjectCli, AFindingIsStoredWithTheAnswersOfAFreshProcess) {
  const TempFolder folder("crosscheck_subject_history");
  const std::string later = subject("wrong_later");
  const Outcome r = campaign(later, folder.path(), {"--seconds", "4", "--max-new", "2"});
  ASSERT_EQ(r.status, 1) << r.out << r.err;
  const auto files = case_files(folder.path() / "found");
  ASSERT_FALSE(files.empty()) << r.out << r.err;
  for (const fs::path& file : files) {
    const harness::Case c = harness::read_case_file(file);
    EXPECT_NE(c.note.find("its worker saw aabb_aabb impl_bug"), std::string::npos) << c.note;
    EXPECT_NE(c.note.find("(a party answers differently in a fresh process)"), std::string::npos) << c.note;
    EXPECT_NE(c.cls, harness::CaseClass::impl_bug) << file;  // right in a fresh process
  }
  const Outcome replay = crosscheck({"replay", "--subject", later, (folder.path() / "found").string()}, folder.path());
  EXPECT_EQ(replay.status, 0) << replay.out << replay.err;
  const std::string n = std::to_string(files.size());
  EXPECT_NE(replay.out.find(n + " cases replayed: " + n + " unchanged, 0 changed"), std::string::npos) << replay.out;

  // Replay asks each case afresh, however many come before it: 120 copies of a finding, each
  // as the first.
  const fs::path copies = folder.path() / "copies";
  fs::create_directories(copies);
  for (int i = 0; i < 120; ++i) fs::copy_file(files.front(), copies / ("copy" + std::to_string(i) + ".json"));
  const Outcome many = crosscheck({"replay", "--subject", later, copies.string()}, folder.path());
  EXPECT_EQ(many.status, 0) << many.out << many.err;
  EXPECT_NE(many.out.find("120 cases replayed: 120 unchanged, 0 changed"), std::string::npos) << many.out;
}

}  // namespace
}  // namespace cc::test
