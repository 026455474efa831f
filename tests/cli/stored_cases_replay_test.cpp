// A case a campaign has just stored replays to the same answers, on a loaded machine too: a short
// campaign over the kinds whose peers crash, time out or answer differently with a history runs
// under a CPU hog (a busy process per core), and its output is then replayed twice: nothing
// changed. (Label property: it is a statement about every stored case.) Broadphase is left out:
// FCL's managers read memory they freed, so on a few cases in a hundred their answer, or
// whether they crash, depends on the heap of the process they run in (README "Broadphase: FCL's managers read memory they freed").
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <set>
#include <string>
#include <vector>

#include "harness/formats/case_file.h"
#include "program_run.h"
#include "temp_folder.h"

namespace cc::test {
namespace {

namespace fs = std::filesystem;

// A process per core that only spins, for as long as this object lives.
class CpuHog {
 public:
  explicit CpuHog(int processes) {
    for (int i = 0; i < processes; ++i) {
      const pid_t pid = ::fork();
      if (pid == 0) {
        volatile unsigned long n = 0;
        for (;;) n = n + 1;
      }
      if (pid > 0) pids_.push_back(pid);
    }
  }
  ~CpuHog() {
    for (const pid_t pid : pids_) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
  }
  std::size_t size() const { return pids_.size(); }

 private:
  std::vector<pid_t> pids_;
};

TEST(StoredCases, ReplayUnchangedTwiceAfterACampaignUnderLoad) {
  const TempFolder folder("stored_cases_replay");
  fs::create_directories(folder.path() / "no_corpus");
  const fs::path out = folder.path() / "found";
  {
    const CpuHog hog(2);
    ASSERT_EQ(hog.size(), 2u);
    const Outcome campaign = run({CROSSCHECK_BINARY, "campaign", "--seconds", "10", "--seed", "7", "--workers", "2",
                                  "--out-of-contract", "30", "--max-new", "40", "--corpora",
                                  (folder.path() / "no_corpus").string(), "--out", out.string(), "--query", "tri_obb",
                                  "--query", "tri_aabb", "--query", "aabb_aabb", "--query",
                                  "obb_obb", "--query", "disc_walls", "--query", "ray_aabb", "--query", "moving_obb"},
                                 folder.path(), folder.path());
    ASSERT_EQ(campaign.status, 0) << campaign.err << campaign.out;

    // The stored cases meet the edges the property is about: several classes, peers failing.
    std::set<std::string> classes;
    int cases = 0;
    for (const fs::path& file : harness::case_files_under({out})) {
      ++cases;
      classes.insert(std::string(harness::to_string(harness::read_case_file(file).cls)));
    }
    EXPECT_GE(cases, 15) << campaign.out;
    EXPECT_GE(classes.size(), 3u);
    EXPECT_TRUE(classes.count("oracle_crash") || classes.count("oracle_defect")) << campaign.out;

    for (int round = 1; round <= 2; ++round) {
      const Outcome replay = run({CROSSCHECK_BINARY, "replay", out.string()}, folder.path(), folder.path());
      EXPECT_EQ(replay.status, 0) << "round " << round << ":\n" << replay.out << replay.err;
      EXPECT_NE(replay.out.find(std::to_string(cases) + " cases replayed: " + std::to_string(cases) + " unchanged, 0 changed"),
                std::string::npos)
          << "round " << round << ":\n" << replay.out;
    }
  }
}

}  // namespace
}  // namespace cc::test
