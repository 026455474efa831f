// crosscheck report: the page of a history folder. The page itself is written by
// src/tool/report/report.py (matplotlib for the plots, Jinja2 for the page), run as a child with
// Debian's Python, which .ci/deps gives those packages.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "tool/child_process.h"
#include "tool/commands.h"
#include "tool/flag_checks.h"

namespace cc::tool {
namespace {

namespace fs = std::filesystem;

struct ReportArgs {
  std::string history, out, known;
};

// $CROSSCHECK_PYTHON, else Debian's python3 (where .ci/deps installs matplotlib and Jinja2) when
// it is there, else the python3 on PATH.
std::string python() {
  if (const char* chosen = std::getenv("CROSSCHECK_PYTHON"); chosen != nullptr && *chosen != '\0') return chosen;
  return access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int run(const ReportArgs& args) {
  const fs::path script = CROSSCHECK_REPORT_SCRIPT;
  if (!fs::is_regular_file(script)) {
    std::fprintf(stderr, "crosscheck report: the page's script %s is missing (report needs the source tree it was built from)\n",
                 script.c_str());
    return kExitIncomplete;
  }
  std::string known = args.known;
  if (known.empty() && fs::is_regular_file("corpora/known_defects.json")) known = "corpora/known_defects.json";
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  std::string log_name = (fs::temp_directory_path() / "crosscheck-report-XXXXXX").string();
  const int fd = mkstemp(log_name.data());
  if (fd < 0) {
    std::fprintf(stderr, "crosscheck report: cannot create a log file in %s\n", fs::temp_directory_path().c_str());
    return kExitIncomplete;
  }
  close(fd);
  std::vector<std::string> argv = {python(), script.string(), "--history", args.history, "--out", args.out};
  if (!error) argv.insert(argv.end(), {"--crosscheck", self.string()});
  if (!known.empty()) argv.insert(argv.end(), {"--known", known});
  const ChildResult r = run_child(argv, {}, log_name, 1800);
  const std::string said = read_all(log_name);
  fs::remove(log_name, error);
  std::fputs(said.c_str(), r.exit_status == 0 ? stdout : stderr);
  if (r.exit_status == 0) return 0;
  if (r.exit_status == kExitBadInput) return kExitBadInput;
  std::fprintf(stderr, "crosscheck report: %s %s %s\n", argv[0].c_str(), script.c_str(),
               !r.started    ? "could not start"
               : r.timed_out ? "ran past 30 minutes"
                             : "failed (is python3-matplotlib and python3-jinja2 installed? .ci/deps installs them)");
  return kExitIncomplete;
}

}  // namespace

void add_report_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ReportArgs>();
  auto* cmd = app.add_subcommand("report", "Write the page of a history folder (campaign --history): trends, the grid of kinds and parties, new findings drawn, known defects");
  cmd->add_option("history", args->history, "The history folder")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--out", args->out, "The folder the page (index.html, self-contained) is written to")
      ->required()
      ->check(writable_folder());
  cmd->add_option("--known", args->known,
                  "Links of known defects to their upstream reports (JSON; default: corpora/known_defects.json if there)")
      ->check(CLI::ExistingFile);
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
