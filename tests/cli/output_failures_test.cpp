// Output that fails loudly, as a user meets it (label hostile): a failed write to standard
// output (a full disk) ends the command with exit 3 and a message; "-" as an output file is
// standard output, never a file named "-"; an output file on a full disk is reported, leaves
// no partial file and loses no finding; a campaign whose output's reader goes away (| head -1)
// still writes its JSON and its findings; a disk with too little room is refused up front.
#include <gtest/gtest.h>

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

// A shell command line run in `folder`, its output and error kept apart.
Outcome shell(const std::string& line, const fs::path& folder) { return run({"sh", "-c", line}, folder, folder); }

const std::string kTool = CROSSCHECK_BINARY;
const std::string kCorpora = std::string(CROSSCHECK_SOURCE_DIR) + "/corpora";

// A short campaign whose findings are sure (out-of-contract aabb_aabb: FCL says hit for inverted
// boxes), into folder/found.
std::string campaign(const fs::path& folder, const std::string& json) {
  fs::create_directories(folder / "no_corpus");
  return kTool + " campaign --query aabb_aabb --out-of-contract 100 --seconds 3 --workers 2 --max-new 3 --out " +
         (folder / "found").string() + " --corpora " + (folder / "no_corpus").string() + " --json " + json;
}

std::size_t case_files(const fs::path& folder) {
  std::size_t n = 0;
  if (fs::exists(folder)) {
    for (const auto& e : fs::recursive_directory_iterator(folder)) n += e.path().extension() == ".json";
  }
  return n;
}

TEST(OutputFailures, AFullStandardOutputIsAnIncompleteRunWithAMessage) {
  const TempFolder folder("crosscheck_output_full");
  const Outcome r = shell(kTool + " replay " + kCorpora + "/aabb_aabb > /dev/full", folder.path());
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("crosscheck replay: cannot write standard output: No space left on device"), std::string::npos) << r.err;
}

TEST(OutputFailures, ADashIsStandardOutputNeverAFileNamedDash) {
  const TempFolder folder("crosscheck_output_dash");
  const Outcome r = shell(campaign(folder.path(), "-"), folder.path());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(folder.path() / "-"));
  const std::size_t start = r.out.find("\n{\n");
  ASSERT_NE(start, std::string::npos) << r.out;
  const harness::Json json = harness::Json::parse(r.out.substr(start + 1));
  EXPECT_GT(json["queries"]["aabb_aabb"]["cases"].get<int>(), 100);
}

TEST(OutputFailures, AJsonOnAFullDiskIsReportedAndTheFindingsAreKept) {
  const TempFolder folder("crosscheck_output_json_full");
  const Outcome r = shell(campaign(folder.path(), "/dev/full"), folder.path());
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("cannot write /dev/full: No space left on device"), std::string::npos) << r.err;
  EXPECT_GT(case_files(folder.path() / "found"), 0u);
}

TEST(OutputFailures, AnOutputFileIsWholeOrAsItWas) {
  const TempFolder folder("crosscheck_output_whole");
  const fs::path svg = folder.path() / "case.svg";
  std::ofstream(svg) << "before";
  // An existing file is replaced whole by the drawing, through a temporary file beside it.
  const std::string case_file = kCorpora + "/sphere_sphere/00a705170f21ad00.json";
  const Outcome ok = shell(kTool + " triage --svg " + svg.string() + " " + case_file, folder.path());
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(text_of(svg).find("</svg>"), std::string::npos) << text_of(svg).substr(0, 80);
  const Outcome dash = shell(kTool + " triage --svg - " + case_file, folder.path());
  EXPECT_EQ(dash.status, 0) << dash.err;
  EXPECT_NE(dash.out.find("<svg"), std::string::npos);
  EXPECT_FALSE(fs::exists(folder.path() / "-"));
  for (const auto& e : fs::directory_iterator(folder.path())) {
    EXPECT_NE(e.path().filename().string().rfind(".case.svg.", 0), 0u) << "a temporary file was left: " << e.path();
  }
}

TEST(OutputFailures, ACampaignWhoseReaderGoesAwayKeepsItsJsonAndFindings) {
  const TempFolder folder("crosscheck_output_pipe");
  const fs::path json = folder.path() / "run.json";
  std::string line = "(";
  line += campaign(folder.path(), json.string());
  line += "; echo $? > status) | head -1";
  const Outcome r = shell(line, folder.path());
  EXPECT_EQ(r.out.rfind("crosscheck campaign: seed", 0), 0u) << r.out;
  ASSERT_TRUE(fs::exists(json)) << r.err;
  EXPECT_GT(harness::Json::parse(text_of(json))["queries"]["aabb_aabb"]["cases"].get<int>(), 100);
  EXPECT_GT(case_files(folder.path() / "found"), 0u);
  const int status = std::stoi(text_of(folder.path() / "status"));
  EXPECT_EQ(status, 3) << "the lost output is reported: " << r.err;
  EXPECT_NE(r.err.find("cannot write standard output"), std::string::npos) << r.err;
}

// A disk with too little room is refused before any work, for a folder and for a file alike,
// and for a file through a link to it: a 512 KiB tmpfs, where this machine lets the test mount
// one (as root); skipped elsewhere.
TEST(OutputFailures, ADiskWithTooLittleRoomIsRefusedBeforeAnyWork) {
  const TempFolder folder("crosscheck_output_tiny_disk");
  const fs::path tiny = folder.path() / "tiny";
  fs::create_directories(tiny);
  if (shell("mount -t tmpfs -o size=512k tmpfs " + tiny.string(), folder.path()).status != 0) {
    GTEST_SKIP() << "no tmpfs can be mounted here";
  }
  const Outcome out = shell(kTool + " campaign --seconds 30 --query sphere_sphere --workers 1 --out " + (tiny / "found").string(),
                            folder.path());
  const Outcome json = shell(kTool + " campaign --seconds 30 --query sphere_sphere --workers 1 --max-new 0 --json " +
                                 (tiny / "run.json").string(),
                             folder.path());
  // A file named by a link elsewhere is written on its target's disk.
  shell("touch tiny/run.json && ln -s tiny/run.json link.json", folder.path());
  const Outcome link = shell(kTool + " campaign --seconds 30 --query sphere_sphere --workers 1 --max-new 0 --json link.json",
                             folder.path());
  shell("umount " + tiny.string(), folder.path());
  EXPECT_EQ(out.status, 2) << out.err;
  EXPECT_NE(out.err.find("--out: only 524288 bytes are free on the disk of " + tiny.string() + " (at least 1 MiB is needed)"),
            std::string::npos)
      << out.err;
  EXPECT_EQ(json.status, 2) << json.err;
  EXPECT_NE(json.err.find("--json: only 524288 bytes are free"), std::string::npos) << json.err;
  EXPECT_EQ(link.status, 2) << link.err;
  EXPECT_NE(link.err.find("--json: only 524288 bytes are free on the disk of link.json"), std::string::npos) << link.err;
}

}  // namespace
}  // namespace cc::test
