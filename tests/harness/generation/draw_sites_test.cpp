// Generators cannot lose a configuration unseen: every line of a generator that draws
// (Choices::draw or Choices::chance, in src/harness/generation and src/harness/kinds) declares a
// choice by being there, and drawing the kinds' cases as a campaign does (and moving them to
// touch, as the fuzz mutator does) must reach every one of those lines and take every branch of each: every value of a draw of at most 16 options and
// both ways of a chance, wherever the draws there make the rarest of them expected at least 20
// times. A branch disabled, a draw that can no longer give its last option, or a line no case
// reaches any more fails here, naming the line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

#include "case_budget.h"
#include "harness/generation/choices.h"
#include "harness/generation/generate.h"
#include "harness/generation/touch.h"
#include "harness/generation/values.h"
#include "test_paths.h"

namespace cc::harness {
namespace {

namespace fs = std::filesystem;

// A source line, "kinds/sphere_sphere.cpp:37", relative to src/harness.
std::string line_key(const std::string& file, std::uint_least32_t line) {
  const std::string marker = "src/harness/";
  const std::size_t at = file.rfind(marker);
  return (at == std::string::npos ? file : file.substr(at + marker.size())) + ":" + std::to_string(line);
}

// One draw or chance of the source (a line may hold several: told apart by their column), with
// one number of options (a draw's may vary from case to case: each is a site of its own).
struct Site {
  std::string line;
  std::uint64_t n = 0;  // a draw's options, or 2 for a chance
  int percent = -1;     // a chance's, or -1 for a draw
  std::uint64_t reached = 0;
  std::map<std::uint64_t, std::uint64_t> values;  // value (or 0/1 for a chance) -> times
};

class Tally final : public DrawRecorder {
 public:
  void drew(DrawSite site, std::uint64_t n, std::uint64_t value) override {
    Site& s = at(site, "draw(" + std::to_string(n) + ")");
    s.n = n;
    ++s.reached;
    if (n <= 16) ++s.values[value];
  }
  void took_chance(DrawSite site, int percent, bool yes) override {
    Site& s = at(site, "chance(" + std::to_string(percent) + ")");
    s.n = 2;
    s.percent = percent;
    ++s.reached;
    ++s.values[yes ? 1 : 0];
  }
  std::map<std::string, Site> sites;  // by line, column and what is drawn there (its n varies)

 private:
  Site& at(DrawSite site, const std::string& what) {
    const std::string line = line_key(site.file_name(), site.line());
    Site& s = sites[line + ":" + std::to_string(site.column()) + " " + what];
    s.line = line;
    return s;
  }
};

// The lines of the generators' sources that draw: a member call of draw( or chance( outside a
// comment.
std::set<std::string> drawing_lines() {
  std::set<std::string> lines;
  const std::regex call(R"((\.|->)(draw|chance)\()");
  for (const char* folder : {"generation", "kinds"}) {
    for (const auto& entry : fs::directory_iterator(fs::path(CROSSCHECK_SOURCE_DIR) / "src" / "harness" / folder)) {
      if (entry.path().extension() != ".cpp") continue;
      std::ifstream in(entry.path());
      std::string text;
      for (std::uint_least32_t number = 1; std::getline(in, text); ++number) {
        const std::size_t comment = text.find("//");
        if (std::regex_search(text.substr(0, comment), call)) {
          lines.insert(line_key(entry.path().string(), number));
        }
      }
    }
  }
  return lines;
}

// Every kind's cases as a campaign draws them (a fifth out of contract), and every other one
// moved to touch as the fuzz mutator moves it, tallied.
const Tally& campaign_draws() {
  static const Tally tally = [] {
    Tally t;
    DrawRecorder& before = record_draws(t);
    for (QueryKind kind : kAllQueryKinds) {
      const int n = test::case_budget(kind, 3000);
      for (int i = 0; i < n; ++i) {
        RandomChoices c(mix_seed(static_cast<std::uint64_t>(kind), static_cast<std::uint64_t>(i)));
        GenerateOptions options;
        options.mesh_folder = test::fcl_mesh_folder();
        options.out_of_contract = i % 5 == 0;
        Input input = generate(kind, c, options);
        if (i % 2 == 0) {
          ValueSource values(c, {});
          make_touching(input, values);
        }
      }
    }
    record_draws(before);
    return t;
  }();
  return tally;
}

TEST(DrawSites, EveryLineThatDrawsIsReached) {
  const std::set<std::string> declared = drawing_lines();
  ASSERT_GT(declared.size(), 100u) << "the generators' sources were not found";
  std::set<std::string> reached;
  for (const auto& [key, site] : campaign_draws().sites) reached.insert(site.line);
  for (const std::string& line : declared) {
    EXPECT_TRUE(reached.contains(line)) << line << " draws, but no generated case reached it";
  }
}

TEST(DrawSites, EveryBranchOfEveryDrawIsTaken) {
  int checked = 0;
  for (const auto& [key, site] : campaign_draws().sites) {
    if (site.n > 16) continue;  // a value, not a branch
    const double rarest = site.percent >= 0 ? std::min(site.percent, 100 - site.percent) / 100.0 : 1.0 / static_cast<double>(site.n);
    if (static_cast<double>(site.reached) * rarest < 20) continue;  // too few draws here to tell
    ++checked;
    for (std::uint64_t value = 0; value < site.n; ++value) {
      EXPECT_GT(site.values.count(value) ? site.values.at(value) : 0, 0u)
          << key << (site.percent >= 0 ? std::string(" never came out ") + (value ? "yes" : "no") : " never gave " + std::to_string(value))
          << " in " << site.reached << " draws";
    }
  }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace cc::harness
