// crosscheck bounds: how close the library's actual rounding comes to each term of its certified
// error bounds over generated cases (harness/judging/bound_coverage.h).
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "collide/bound_records.h"
#include "harness/judging/bound_coverage.h"
#include "harness/generation/generate.h"
#include "harness/formats/mesh_files.h"
#include "oracle/exact/exact_reference.h"
#include "tool/output_file.h"
#include "tool/commands.h"
#include "tool/flag_checks.h"

namespace cc::tool {
namespace {

struct BoundsArgs {
  std::vector<std::string> queries;
  int cases = 2000;
  std::uint64_t seed = 1;
  std::string corpora = "corpora";
  std::string json;
};

int run(const BoundsArgs& args) {
  std::vector<harness::QueryKind> kinds;
  for (const std::string& q : args.queries) {
    const auto kind = harness::query_kind_named(q);
    if (!kind) {
      std::fprintf(stderr, "crosscheck bounds: unknown query \"%s\"\n", q.c_str());
      return kExitBadInput;
    }
    kinds.push_back(*kind);
  }
  if (kinds.empty()) {
    for (const harness::ExpectedTerm& e : harness::expected_terms()) {
      if (std::find(kinds.begin(), kinds.end(), e.kind) == kinds.end()) kinds.push_back(e.kind);
    }
  }
  const exact::ExactRationalReference exact;
  harness::GenerateOptions options;
  options.mesh_folder = harness::mesh_folder(args.corpora);
  options.exact = &exact;
  harness::BoundCoverage coverage;
  std::printf("crosscheck bounds: seed %llu, %d cases per primitive query kind (a twentieth for meshes)\n\n",
              static_cast<unsigned long long>(args.seed), args.cases);
  for (harness::QueryKind kind : kinds) {
    const bool meshes = harness::builds_hierarchies(kind);
    const int n = meshes ? std::max(1, args.cases / 20) : args.cases;
    for (int i = 0; i < n; ++i) {
      harness::RandomChoices choices(harness::mix_seed(args.seed, static_cast<std::uint64_t>(i)));
      coverage.add(harness::generate(kind, choices, options), exact);
    }
  }
  const auto rows = coverage.rows(kinds);
  std::printf("%s", harness::format_coverage(rows).c_str());
  std::printf("\nclosest: the largest actual error / term over the quantities measured (a term's error is the\n"
              "part of the rounding it covers; total: the whole bound, slack included, must stay <= 1);\n"
              "a term not approached within 2^-8 is one no case needs.\n");
  bool ok = true;
  nlohmann::json rows_json = nlohmann::json::array();
  for (const harness::TermCoverage& row : rows) {
    ok &= row.ok();
    const auto inputs = [](const std::string& json) { return json.empty() ? nlohmann::json() : nlohmann::json::parse(json); };
    rows_json.push_back({{"test", row.test},
                         {"quantity", row.quantity},
                         {"term", row.term},
                         {"closest", row.closest},
                         {"quantities", row.quantities},
                         {"cases", row.cases},
                         {"largest", row.largest},
                         {"ok", row.ok()},
                         {"closest_case", inputs(row.closest_case)},
                         {"largest_case", inputs(row.largest_case)}});
  }
  if (!args.json.empty()) {
    const std::string why =
        write_output_file(args.json, nlohmann::json{{"seed", args.seed}, {"cases", args.cases}, {"rows", rows_json}}.dump(2) + "\n");
    if (!why.empty()) {
      std::fprintf(stderr, "crosscheck bounds: %s\n", why.c_str());
      return kExitIncomplete;
    }
  }
  return ok ? 0 : kExitFound;
}

}  // namespace

void add_bounds_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<BoundsArgs>();
  auto* cmd = app.add_subcommand("bounds", "How close the actual rounding comes to each term of the library's error bounds");
  cmd->add_option("--query", args->queries, "A query kind to measure (repeatable; default: all with a bound)")
      ->check(query_kind_name());
  cmd->add_option("--cases", args->cases, "Generated cases per primitive query kind")
      ->capture_default_str()
      ->check(whole_in(1, 100000000));
  cmd->add_option("--seed", args->seed, "Seed of the case generator")->capture_default_str()->check(seed_value());
  cmd->add_option("--corpora", args->corpora, "Where FCL's test meshes are (corpora/meshes)")
      ->capture_default_str()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--json", args->json, "Write every row, with the case of its closest approach, to this JSON file")
      ->check(writable_file());
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
