// crosscheck triage FILE... [--svg OUT]: the three answers, the class, the margin and the exact
// reference's reasoning for each case file; --svg draws a single case.
#include <cstdio>
#include <fstream>
#include <optional>

#include "harness/judging/query_cost.h"
#include "harness/model/input.h"
#include "oracle/exact/exact_reference.h"
#include "harness/model/subject.h"
#include "tool/output_file.h"
#include "tool/cases.h"
#include "tool/commands.h"
#include "tool/subject_option.h"
#include "tool/flag_checks.h"

namespace cc::tool {
namespace {

// A mesh query's counters and the cost function T = n_v c_v + n_p c_p + n_u c_u, with unit
// costs measured now on the case's own volumes and triangles.
void print_cost(const harness::Input& input) {
  const harness::MeshPair* m = harness::meshes_of(input);
  const std::optional<CollisionMode> mode = harness::mesh_mode_of(input);
  if (m == nullptr || !mode) return;
  const harness::QueryCost c = harness::measure_query_cost(*m, *mode);
  const auto n = [](std::uint64_t x) { return static_cast<double>(x); };
  std::printf("  counters   n_v = %llu volume tests, n_p = %llu triangle tests, n_u = %llu volume updates\n",
              static_cast<unsigned long long>(c.counters.bv_tests), static_cast<unsigned long long>(c.counters.primitive_tests),
              static_cast<unsigned long long>(c.counters.bv_updates));
  std::printf("  unit cost  c_v = %.1f ns, c_p = %.1f ns, c_u = %.1f ns (%s, %s update; medians of 5 batches)\n",
              c.unit.bv_test, c.unit.primitive_test, c.unit.bv_update, std::string(to_string(m->library.bv)).c_str(),
              std::string(to_string(m->library.update)).c_str());
  std::printf("  cost       T = %.1f + %.1f + %.1f = %.1f us; measured %.1f us (median of 5)\n",
              n(c.counters.bv_tests) * c.unit.bv_test / 1e3, n(c.counters.primitive_tests) * c.unit.primitive_test / 1e3,
              n(c.counters.bv_updates) * c.unit.bv_update / 1e3, c.predicted_ns / 1e3, c.measured_ns / 1e3);
}

struct TriageArgs {
  std::vector<std::string> files;
  std::string svg;
  std::string subject;
};

int run(const TriageArgs& args) {
  if (!args.svg.empty() && args.files.size() != 1) {
    std::fprintf(stderr, "crosscheck triage: --svg draws one case; %zu files given\n", args.files.size());
    return kExitBadInput;
  }
  put_subject_under_test(args.subject, kPartyTimeLimit);
  const exact::ExactRationalReference exact;
  int status = 0;
  for (const std::string& file : args.files) {
    const auto c = read_case_or_report(file);
    if (!c) {
      status = kExitBadInput;
      continue;
    }
    if (!subject_fits_case(*c, file, "triage")) {
      status = kExitBadInput;
      continue;
    }
    if (!harness::library_answers(harness::kind_of(c->input))) {
      std::fprintf(stderr, "crosscheck triage: %s: the subject does not answer %s\n", file.c_str(),
                   std::string(name(harness::kind_of(c->input))).c_str());
      status = kExitBadInput;
      continue;
    }
    const harness::Evaluation now = evaluate_surviving_crashes(c->input);
    const harness::Explanation why = exact.explain(c->input);
    std::printf("%s", triage_text(file, *c, now, why).c_str());
    print_cost(c->input);
    std::printf("\n");
    if (!args.svg.empty()) {
      const std::string failed = write_output_file(
          args.svg, svg_of(c->input, why,
                           file + ": " + std::string(name(harness::kind_of(c->input))) + ", " + std::string(to_string(now.verdict.cls))));
      if (!failed.empty()) {
        std::fprintf(stderr, "crosscheck triage: %s\n", failed.c_str());
        return kExitIncomplete;
      }
      if (args.svg != "-") std::printf("drawn in %s\n", args.svg.c_str());
    }
  }
  return status;
}

}  // namespace

void add_triage_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<TriageArgs>();
  auto* cmd = app.add_subcommand("triage", "Explain case files: answers, class, margin and the deciding axis or slab");
  cmd->add_option("files", args->files, "Case files")->required();
  cmd->add_option("--svg", args->svg, "Draw the case (three views and the deciding axis) into this SVG file")
      ->check(writable_file());
  add_subject_option(cmd, args->subject);
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
