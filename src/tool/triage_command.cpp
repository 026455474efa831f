// crosscheck triage FILE... [--svg OUT]: the three answers, the class, the margin and the exact
// reference's reasoning for each case file; --svg draws a single case.
#include <cstdio>
#include <fstream>

#include "oracle/exact/exact_reference.h"
#include "tool/cases.h"
#include "tool/commands.h"

namespace cc::tool {
namespace {

struct TriageArgs {
  std::vector<std::string> files;
  std::string svg;
};

int run(const TriageArgs& args) {
  if (!args.svg.empty() && args.files.size() != 1) {
    std::fprintf(stderr, "crosscheck triage: --svg draws one case; %zu files given\n", args.files.size());
    return kExitBadInput;
  }
  const exact::ExactRationalReference exact;
  int status = 0;
  for (const std::string& file : args.files) {
    const auto c = read_case_or_report(file);
    if (!c) {
      status = kExitBadInput;
      continue;
    }
    const harness::Evaluation now = evaluate_with_oracles(c->input);
    const harness::Explanation why = exact.explain(c->input);
    std::printf("%s\n", triage_text(file, *c, now, why).c_str());
    if (!args.svg.empty()) {
      std::ofstream out(args.svg);
      out << svg_of(c->input, why);
      if (!out) {
        std::fprintf(stderr, "crosscheck triage: cannot write %s\n", args.svg.c_str());
        return kExitBadInput;
      }
      std::printf("drawn in %s\n", args.svg.c_str());
    }
  }
  return status;
}

}  // namespace

void add_triage_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<TriageArgs>();
  auto* cmd = app.add_subcommand("triage", "Explain case files: answers, class, margin and the deciding axis or slab");
  cmd->add_option("files", args->files, "Case files")->required();
  cmd->add_option("--svg", args->svg, "Draw the case (three views and the deciding axis) into this SVG file");
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
