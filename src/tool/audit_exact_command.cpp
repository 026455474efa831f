// crosscheck audit-exact: the exact reference audited by CGAL's exact kernel. Runs the campaign's
// cases of each kind CGAL answers (or those named) through both for a time budget and prints, per
// kind, how many were compared and how many disagree; each disagreement is printed and stored as
// a case file of class exact_defect.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "harness/formats/case_file.h"
#include "harness/formats/input_json.h"
#include "harness/model/library.h"
#include "harness/processes/campaign.h"
#include "oracle/cgal/exact_audit.h"
#include "oracle/exact/exact_reference.h"
#include "tool/commands.h"
#include "tool/flag_checks.h"

namespace cc::tool {
namespace {

using namespace harness;
using cgal::AuditOutcome;

struct AuditArgs {
  std::vector<std::string> queries;
  double seconds = 60;
  std::uint64_t seed = 1;
  std::string out = "corpora/new";
};

struct KindAudit {
  std::uint64_t cases = 0, compared = 0, out_of_contract = 0, undecided = 0, touching = 0, disagreements = 0;
  double seconds = 0;
};

std::vector<std::string> audited_kind_names() {
  std::vector<std::string> names;
  for (QueryKind kind : kAllQueryKinds) {
    if (cgal::answers(kind)) names.emplace_back(name(kind));
  }
  return names;
}

// Prints the disagreement and stores it as a new case file; false if it could not be stored.
bool store(const Input& input, const cgal::Audit& audit, const AuditArgs& args, std::uint64_t index) {
  const QueryKind kind = kind_of(input);
  std::printf("\nexact_defect on %s (case %llu): %s\n  inputs %s\n", std::string(name(kind)).c_str(),
              static_cast<unsigned long long>(index), audit.why.c_str(), input_to_json(input).dump().c_str());
  Case c;
  c.input = input;
  c.library = ask_library(input);
  c.exact = audit.exact;
  c.opinions = {Opinion{"cgal.exact", Opinion::Status::answered, Answer::of(audit.cgal.hit), audit.why, std::nullopt}};
  c.cls = CaseClass::exact_defect;
  c.provenance = {"campaign", args.seed, index, "crosscheck audit-exact, seed " + std::to_string(args.seed)};
  c.note = "untriaged: " + audit.why;
  const auto path = std::filesystem::path(args.out) / std::string(name(kind)) / case_file_name(input);
  try {
    const auto written = write_new_case_file(path, c);
    std::printf("  %s %s\n", written ? "written to" : "already stored as", (written ? *written : path).string().c_str());
    return true;
  } catch (const CaseFileError& e) {
    std::fprintf(stderr, "crosscheck audit-exact: %s\n", e.what());
    return false;
  }
}

KindAudit audit_kind(QueryKind kind, double seconds, const AuditArgs& args, const ExactReference& exact,
                     bool& store_failed) {
  using Clock = std::chrono::steady_clock;
  const int out_of_contract_percent = CampaignOptions{}.out_of_contract_percent;
  KindAudit t;
  const auto start = Clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  for (std::uint64_t index = 0; t.cases == 0 || index % 64 != 0 || elapsed() < seconds; ++index) {
    const Input input = campaign_case(args.seed, kind, index, out_of_contract_percent);
    const cgal::Audit a = cgal::audit_case(input, exact);
    ++t.cases;
    switch (a.outcome) {
      case AuditOutcome::out_of_contract: ++t.out_of_contract; continue;
      case AuditOutcome::undecided: ++t.undecided; continue;
      case AuditOutcome::disagree:
        ++t.disagreements;
        store_failed |= !store(input, a, args, index);
        break;
      case AuditOutcome::agree: break;
    }
    ++t.compared;
    t.touching += a.touching();
  }
  t.seconds = elapsed();
  return t;
}

int run(const AuditArgs& args) {
  std::vector<QueryKind> kinds;
  for (const std::string& q : args.queries) kinds.push_back(*query_kind_named(q));  // checked by --query
  if (kinds.empty()) {
    for (QueryKind kind : kAllQueryKinds) {
      if (cgal::answers(kind)) kinds.push_back(kind);
    }
  }
  std::printf("crosscheck audit-exact: seed %llu, %g s, %zu query kinds, the exact reference against CGAL's exact "
              "kernel\n",
              static_cast<unsigned long long>(args.seed), args.seconds, kinds.size());
  std::fflush(stdout);
  const exact::ExactRationalReference exact;
  std::vector<KindAudit> tallies;
  bool store_failed = false;
  for (QueryKind kind : kinds) {
    tallies.push_back(audit_kind(kind, args.seconds / static_cast<double>(kinds.size()), args, exact, store_failed));
    std::fflush(stdout);
  }
  std::printf("\n%-*s %10s %10s %16s %10s %10s %13s %10s\n", harness::longest_kind_name(), "query", "cases", "compared",
              "out_of_contract", "undecided", "touching", "exact_defect", "cases/s");
  std::uint64_t disagreements = 0;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    const KindAudit& t = tallies[i];
    disagreements += t.disagreements;
    std::printf("%-*s %10llu %10llu %16llu %10llu %10llu %13llu %10.0f\n", harness::longest_kind_name(),
                std::string(name(kinds[i])).c_str(), static_cast<unsigned long long>(t.cases),
                static_cast<unsigned long long>(t.compared), static_cast<unsigned long long>(t.out_of_contract),
                static_cast<unsigned long long>(t.undecided), static_cast<unsigned long long>(t.touching),
                static_cast<unsigned long long>(t.disagreements),
                t.seconds > 0 ? static_cast<double>(t.cases) / t.seconds : 0.0);
  }
  if (store_failed) std::fprintf(stderr, "crosscheck audit-exact: some disagreements could not be stored\n");
  return disagreements > 0 ? kExitFound : 0;
}

}  // namespace

void add_audit_exact_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<AuditArgs>();
  auto* cmd = app.add_subcommand("audit-exact", "Audit the exact reference with CGAL's exact kernel");
  cmd->add_option("--query", args->queries, "A query kind to audit (repeatable; default: all that CGAL answers)")
      ->check(CLI::IsMember(audited_kind_names()));
  cmd->add_option("--seconds", args->seconds, "Time budget in seconds, shared equally by the kinds")
      ->check(finite_above(0, 604800))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the case generator (the campaign's)")
      ->capture_default_str()
      ->check(seed_value());
  cmd->add_option("--out", args->out, "Where disagreements are written as case files")->capture_default_str();
  // --out is checked up front even when left at its default: disagreements are written at once.
  cmd->callback([args, &exit_code] {
    if (const std::string why = unwritable_folder(args->out); !why.empty()) {
      std::fprintf(stderr, "crosscheck audit-exact: --out: %s\n", why.c_str());
      exit_code = kExitBadInput;
      return;
    }
    exit_code = run(*args);
  });
}

}  // namespace cc::tool
