// The campaign keeps its promises as a user meets them, run as its own process: SIGINT or
// SIGTERM to its pid alone (not its group) stops every worker within a second and still writes
// the JSON and a case file for every kind of finding; a second SIGINT stores the rest as found
// at once; --seconds bounds the whole run; two campaigns writing into one folder lose nothing
// and count exactly what they wrote.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "harness/formats/case_file.h"
#include "harness/processes/child.h"
#include "temp_folder.h"

namespace cc::test {
namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// `crosscheck campaign ...` started in a process group of its own (so that a signal to its pid
// alone is the test), its output in `log`. Findings come reliably from out-of-contract
// aabb_aabb cases: FCL's AABBd::overlap says hit for inverted or NaN boxes, where the library
// documents miss.
// `wrapper` (a command that runs the rest) comes first when given.
harness::Child start_campaign(const std::vector<std::string>& args, const fs::path& log,
                              const std::vector<std::string>& wrapper = {}) {
  std::vector<std::string> all = wrapper;
  all.insert(all.end(), {CROSSCHECK_BINARY, "campaign", "--query", "aabb_aabb", "--out-of-contract", "100"});
  const std::pair<std::string, std::string> defaults[] = {
      {"--workers", "2"}, {"--max-new", "1000"}, {"--corpora", (log.parent_path() / "no_corpus").string()}};
  for (const auto& [flag, value] : defaults) {
    if (std::find(args.begin(), args.end(), flag) == args.end()) all.insert(all.end(), {flag, value});
  }
  all.insert(all.end(), args.begin(), args.end());
  fs::create_directories(log.parent_path() / "no_corpus");
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string log_path = log.string();
  return harness::start_child([&](int) {
    ::setpgid(0, 0);
    const int fd = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::execvp(argv[0], argv.data());
    return 127;
  });
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::set<fs::path> case_files(const fs::path& folder) {
  std::set<fs::path> files;
  if (!fs::exists(folder)) return files;
  for (const auto& e : fs::recursive_directory_iterator(folder)) {
    if (e.is_regular_file()) files.insert(e.path());
  }
  return files;
}

// The JSON's promises: every finding has a case file (its own or its group's) that exists and
// reads back; the files written are exactly those on disk; nothing is left half written.
void expect_every_finding_stored(const harness::Json& json, const fs::path& out, const std::string& log) {
  ASSERT_FALSE(json["findings"].empty()) << log;
  std::set<fs::path> named;
  for (const harness::Json& f : json["findings"]) {
    const std::string stored = f["stored"];
    ASSERT_TRUE(stored == "written" || stored == "grouped" || stored == "already stored") << f.dump() << "\n" << log;
    ASSERT_TRUE(f.contains("case_file")) << f.dump();
    const fs::path file = f["case_file"].get<std::string>();
    EXPECT_TRUE(fs::exists(file)) << file;
    if (stored == "written") named.insert(file);
  }
  const std::set<fs::path> on_disk = case_files(out);
  EXPECT_EQ(on_disk, named) << "files on disk and files the JSON says were written";
  EXPECT_EQ(json["stored"]["written"].get<std::size_t>(), on_disk.size());
  for (const fs::path& file : on_disk) {
    EXPECT_EQ(file.extension(), ".json") << "a temporary file was left: " << file;
    EXPECT_NO_THROW(harness::read_case_file(file)) << file;
  }
}

// Sends `signals` to the campaign's pid alone, 1.5 s after its start and then `gap` apart; checks
// that it exits with 128 + the first signal, within `limit` seconds of the last, having stopped its
// cases within a second, leaving no process of its group behind, with the JSON and every finding.
void interrupt_and_check(const std::vector<int>& signals, double gap, double limit) {
  TempFolder folder("crosscheck_campaign_signals");
  const fs::path out = folder.path() / "new", json_path = folder.path() / "run.json", log = folder.path() / "log";
  const auto start = Clock::now();
  harness::Child child = start_campaign({"--seconds", "60", "--out", out.string(), "--json", json_path.string()}, log);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  for (std::size_t i = 0; i < signals.size(); ++i) {
    if (i > 0) std::this_thread::sleep_for(std::chrono::duration<double>(gap));
    ASSERT_EQ(::kill(child.pid, signals[i]), 0);
  }
  const auto signalled = Clock::now();
  const harness::ChildEnd end = harness::finish_child(child, 30);  // its workers hold the pipe too
  const double after_signal = since(signalled);
  const std::string output = text_of(log);
  ASSERT_FALSE(end.timed_out) << output;
  EXPECT_EQ(end.status, 128 + signals[0]) << output;
  EXPECT_LT(after_signal, limit) << output;
  EXPECT_EQ(::kill(-child.pid, 0), -1) << "a process of the campaign's group is still running";
  ASSERT_TRUE(fs::exists(json_path)) << output;
  const harness::Json json = harness::Json::parse(text_of(json_path));
  EXPECT_TRUE(json["interrupted"].get<bool>());
  EXPECT_EQ(json["signal"].get<int>(), signals[0]);
  // The cases stopped within a second of the signal (the run began before the 1.5 s).
  EXPECT_LT(json["seconds"].get<double>(), 1.5 + 1.0 + 0.5) << output;
  EXPECT_LT(json["seconds"].get<double>(), since(start));
  expect_every_finding_stored(json, out, output);
  EXPECT_NE(output.find("-> " + out.string()), std::string::npos) << "no finding line names its case file:\n" << output;
}

TEST(CampaignSignals, SigintToItsPidAloneStopsTheWorkersAndKeepsEverything) { interrupt_and_check({SIGINT}, 0, 8); }

TEST(CampaignSignals, SigtermToItsPidAloneStopsTheWorkersAndKeepsEverything) { interrupt_and_check({SIGTERM}, 0, 8); }

TEST(CampaignSignals, SighupToItsPidAloneStopsTheWorkersAndKeepsEverything) { interrupt_and_check({SIGHUP}, 0, 8); }

TEST(CampaignSignals, ASecondSigintStoresTheRestAsFoundAtOnce) { interrupt_and_check({SIGINT, SIGINT}, 0.2, 3); }

// With no time left to shrink, findings are stored as found and marked so, in the case file
// and in the JSON.
TEST(CampaignBudget, FindingsWithNoTimeLeftAreStoredAsFoundAndMarked) {
  TempFolder folder("crosscheck_campaign_budget");
  const fs::path out = folder.path() / "new", json_path = folder.path() / "run.json", log = folder.path() / "log";
  const harness::ChildEnd end = harness::finish_child(
      start_campaign({"--seconds", "0.1", "--out", out.string(), "--json", json_path.string()}, log), 30);
  const std::string output = text_of(log);
  ASSERT_EQ(end.status, 0) << output;
  const harness::Json json = harness::Json::parse(text_of(json_path));
  expect_every_finding_stored(json, out, output);
  for (const harness::Json& f : json["findings"]) {
    if (f["stored"] != "written") continue;
    EXPECT_EQ(f["not_shrunk"], "no time left in --seconds") << f.dump();
    EXPECT_EQ(harness::read_case_file(f["case_file"].get<std::string>()).not_shrunk, "no time left in --seconds");
  }
  EXPECT_EQ(json["stored"]["shrunk"], 0);
}

// A fork that fails (here: a process limit for an unprivileged user) costs the campaign that
// worker, reported with the reason and exit status 3, never an abort or a worker left behind.
TEST(CampaignWorkers, AFailedForkIsReportedNotAnAbort) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to run the campaign as another user under a process limit";
  TempFolder folder("crosscheck_campaign_fork");
  fs::permissions(folder.path(), fs::perms::all);
  const fs::path json_path = folder.path() / "run.json", log = folder.path() / "log";
  harness::Child child =
      start_campaign({"--seconds", "1", "--workers", "3", "--max-new", "0", "--json", json_path.string()}, log,
                     {"setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", "prlimit", "--nproc=2"});
  const harness::ChildEnd end = harness::finish_child(child, 30);
  const std::string output = text_of(log);
  if (end.status == 127 || output.find("crosscheck campaign:") == std::string::npos) {
    GTEST_SKIP() << "setpriv or prlimit cannot run here: " << output;
  }
  EXPECT_EQ(end.status, 3) << output;
  EXPECT_EQ(::kill(-child.pid, 0), -1) << "a process of the campaign's group is still running";
  const harness::Json json = harness::Json::parse(text_of(json_path));
  ASSERT_FALSE(json["problems"].empty()) << output;
  EXPECT_NE(json["problems"][0].get<std::string>().find("could not be started (fork: "), std::string::npos)
      << json["problems"].dump();
  EXPECT_LT(json["workers"].get<int>(), 3);
  EXPECT_NE(output.find("PROBLEM: worker "), std::string::npos) << output;
}

// Two campaigns of the same seed into one folder: they find the same cases, so they race for
// the same names; each file is created by one of them, and their counts add up to the files.
TEST(CampaignFiles, TwoCampaignsIntoOneFolderLoseNothingAndCountExactly) {
  TempFolder folder("crosscheck_campaign_files");
  const fs::path out = folder.path() / "new";
  const auto start = Clock::now();
  std::vector<harness::Child> children;
  for (int i = 0; i < 2; ++i) {
    const std::string n = std::to_string(i);
    children.push_back(start_campaign({"--seconds", "3", "--seed", "7", "--out", out.string(), "--json",
                                       (folder.path() / ("run" + n + ".json")).string()},
                                      folder.path() / ("log" + n)));
  }
  std::size_t written = 0;
  std::set<fs::path> named;
  for (int i = 0; i < 2; ++i) {
    const harness::ChildEnd end = harness::finish_child(children[static_cast<std::size_t>(i)], 30);
    const std::string output = text_of(folder.path() / ("log" + std::to_string(i)));
    ASSERT_EQ(end.status, 0) << output;
    const harness::Json json = harness::Json::parse(text_of(folder.path() / ("run" + std::to_string(i) + ".json")));
    written += json["stored"]["written"].get<std::size_t>();
    for (const harness::Json& f : json["findings"]) {
      if (f["stored"] == "written") named.insert(f["case_file"].get<std::string>());
      if (f.contains("case_file")) {
        EXPECT_TRUE(fs::exists(f["case_file"].get<std::string>())) << f.dump();
      }
    }
  }
  // --seconds bounds each whole run (cases and shrinking); both ran side by side.
  EXPECT_LT(since(start), 3 + 4.5);
  const std::set<fs::path> on_disk = case_files(out);
  EXPECT_GT(on_disk.size(), 0u);
  EXPECT_EQ(written, on_disk.size());
  EXPECT_EQ(named, on_disk);
}

}  // namespace
}  // namespace cc::test
