// Every flag of every command, as a user meets it: for each flag whose --help gives a range
// (NUMBER, INT or SEED in [lo, hi] or (lo, hi]), the smallest and largest values accepted pass and the
// first refused value on each side ends the run with exit status 2 and "--flag: must be ...";
// for each output flag (FILE or FOLDER, writable), an existing file or folder passes with not a
// byte changed and nothing left beside it, a new file passes and is not left behind, the other
// kind of path is refused, and "-" passes as a file. Nothing runs: every invocation ends with a flag no command has, which CLI11 refuses
// only once every given flag has passed its check (a command with a required argument may end
// on that instead).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli/program_run.h"
#include "temp_folder.h"

namespace cc::test {
namespace {

namespace fs = std::filesystem;

const std::string kTool = CROSSCHECK_BINARY;
const std::string kSentinel = "--crosscheck-test-sentinel";

struct Flag {
  std::string command, name, type;  // type: NUMBER, INT, FILE or FOLDER
  bool lo_open = false;
  std::string lo, hi;
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The subcommands, from `crosscheck --help`.
std::vector<std::string> commands(const fs::path& scratch) {
  std::vector<std::string> out;
  bool in_list = false;
  for (const std::string& line : lines_of(run({kTool, "--help"}, scratch, scratch).out)) {
    if (line == "Subcommands:") {
      in_list = true;
    } else if (in_list && line.empty()) {
      break;
    } else if (in_list) {
      std::istringstream words(line);
      std::string name;
      words >> name;
      out.push_back(name);
    }
  }
  return out;
}

// Every flag of every command with a range or an output path, from each command's --help.
std::vector<Flag> flags(const fs::path& scratch) {
  static const std::regex range(R"(^\s+(?:-\w,)?(--[\w-]+) \w+:(NUMBER|INT|SEED) in ([\[(])([^,]+), ([^\]]+)\])");
  static const std::regex output(R"(^\s+(?:-\w,)?(--[\w-]+) \w+:(FILE|FOLDER) \(writable\))");
  std::vector<Flag> out;
  for (const std::string& command : commands(scratch)) {
    for (const std::string& line : lines_of(run({kTool, command, "--help"}, scratch, scratch).out)) {
      std::smatch m;
      if (std::regex_search(line, m, range)) {
        out.push_back({command, m[1], m[2], m[3] == "(", m[4], m[5]});
      } else if (std::regex_search(line, m, output)) {
        out.push_back({command, m[1], m[2]});
      }
    }
  }
  return out;
}

std::string text_of_double(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// The run of `command --flag value` that does nothing: passed, or refused naming the flag.
struct Verdict {
  bool passed = false, refused = false;
  std::string output;
};
Verdict check(const Flag& f, const std::string& value, const fs::path& scratch) {
  const Outcome r = run({kTool, f.command, f.name, value, kSentinel}, scratch, scratch);
  Verdict v;
  v.output = r.out + r.err;
  const bool named = v.output.find(f.name + ": ") != std::string::npos;
  v.refused = r.status == 2 && named;
  v.passed = r.status == 2 && !named &&
             (v.output.find(kSentinel) != std::string::npos || v.output.find("is required") != std::string::npos);
  return v;
}

TEST(FlagRanges, EveryRangeIsExactAtBothEnds) {
  const TempFolder folder("crosscheck_flag_ranges");
  int ranges = 0;
  for (const Flag& f : flags(folder.path())) {
    if (f.type != "NUMBER" && f.type != "INT" && f.type != "SEED") continue;
    ++ranges;
    const std::string what = f.command + " " + f.name + " in " + (f.lo_open ? "(" : "[") + f.lo + ", " + f.hi + "]";
    std::vector<std::string> pass, refuse;
    if (f.type == "SEED") {  // [0, 2^64 - 1], a sign refused
      pass = {"0", "18446744073709551615"};
      refuse = {"-1", "18446744073709551616"};
    } else if (f.type == "INT") {
      const long long lo = std::stoll(f.lo), hi = std::stoll(f.hi);
      pass = {std::to_string(lo), std::to_string(hi)};
      refuse = {std::to_string(lo - 1), std::to_string(hi + 1)};
    } else {
      const double lo = std::strtod(f.lo.c_str(), nullptr), hi = std::strtod(f.hi.c_str(), nullptr);
      pass = {text_of_double(f.lo_open ? std::nextafter(lo, INFINITY) : lo), text_of_double(hi)};
      refuse = {text_of_double(f.lo_open ? lo : std::nextafter(lo, -INFINITY)), text_of_double(std::nextafter(hi, INFINITY))};
    }
    for (const std::string& value : pass) {
      const Verdict v = check(f, value, folder.path());
      EXPECT_TRUE(v.passed) << what << ": " << value << " should pass\n" << v.output;
    }
    for (const std::string& value : refuse) {
      const Verdict v = check(f, value, folder.path());
      EXPECT_TRUE(v.refused) << what << ": " << value << " should be refused naming the flag\n" << v.output;
      EXPECT_NE(v.output.find(f.name + ": must be"), std::string::npos) << what << ": " << value << "\n" << v.output;
    }
  }
  EXPECT_GE(ranges, 30) << "the --help pages name fewer ranges than the tool has";
}

TEST(FlagRanges, EveryOutputFlagLeavesWhatExistsAsItWas) {
  const TempFolder folder("crosscheck_flag_outputs");
  int outputs = 0;
  for (const Flag& f : flags(folder.path())) {
    if (f.type != "FILE" && f.type != "FOLDER") continue;
    ++outputs;
    const std::string what = f.command + " " + f.name + " (" + f.type + ")";
    const fs::path place = folder.path() / "place";
    fs::remove_all(place);
    fs::create_directories(place);
    const fs::path file = place / "existing.txt";
    const std::string bytes = "kept as it was\n";
    std::ofstream(file, std::ios::binary) << bytes;
    const fs::path good = f.type == "FILE" ? file : place;
    const fs::path wrong = f.type == "FILE" ? place : file;
    const Verdict kept = check(f, good.string(), folder.path());
    EXPECT_TRUE(kept.passed) << what << ": " << good << "\n" << kept.output;
    EXPECT_EQ(text_of(file), bytes) << what << ": the probe changed the file";
    EXPECT_EQ(std::distance(fs::directory_iterator(place), fs::directory_iterator()), 1) << what << ": a probe was left";
    const Verdict refused = check(f, wrong.string(), folder.path());
    EXPECT_TRUE(refused.refused) << what << ": " << wrong << "\n" << refused.output;
    if (f.type == "FILE") {  // a new file is tried and removed again
      const Verdict fresh = check(f, (place / "new.txt").string(), folder.path());
      EXPECT_TRUE(fresh.passed) << what << ": a new file\n" << fresh.output;
      EXPECT_FALSE(fs::exists(place / "new.txt")) << what << ": the probe left the file it tried";
    }
    if (f.type == "FILE") {
      const Verdict dash = check(f, "-", folder.path());
      EXPECT_TRUE(dash.passed) << what << ": - is standard output\n" << dash.output;
      EXPECT_FALSE(fs::exists(folder.path() / "-")) << what;
    }
  }
  EXPECT_GE(outputs, 8) << "the --help pages name fewer output flags than the tool has";
}

}  // namespace
}  // namespace cc::test
