// crosscheck campaign: the main job. Runs every query kind (or those named) for a time budget
// and prints a table of classes per kind; each impl_bug, oracle_defect and oracle_crash is
// printed with its exact inputs.
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <thread>

#include "harness/campaign.h"
#include "harness/input_json.h"
#include "tool/commands.h"
#include "tool/oracles.h"

namespace cc::tool {
namespace {

using namespace harness;

struct CampaignArgs {
  std::vector<std::string> queries;
  double seconds = 60;
  std::uint64_t seed = 1;
  int workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  double timeout = 20;
  int out_of_contract = 10;
  std::string json;
  int max_print = 20;
};

void print_table(const CampaignResult& r) {
  std::printf("\n%-14s %10s %10s %9s %14s %13s %9s %16s %10s %10s\n", "query", "cases", "agree", "impl_bug",
              "oracle_defect", "oracle_crash", "boundary", "out_of_contract", "undecided", "cases/s");
  for (const auto& [kind, t] : r.tallies) {
    std::printf("%-14s %10llu %10llu %9llu %14llu %13llu %9llu %16llu %10llu %10.0f\n",
                std::string(name(kind)).c_str(), static_cast<unsigned long long>(t.cases),
                static_cast<unsigned long long>(t.count(CaseClass::agree)),
                static_cast<unsigned long long>(t.count(CaseClass::impl_bug)),
                static_cast<unsigned long long>(t.count(CaseClass::oracle_defect)),
                static_cast<unsigned long long>(t.count(CaseClass::oracle_crash)),
                static_cast<unsigned long long>(t.count(CaseClass::boundary)),
                static_cast<unsigned long long>(t.count(CaseClass::out_of_contract)),
                static_cast<unsigned long long>(t.count(CaseClass::undecided)), cases_per_second(t, r.workers));
  }
}

std::string summary_of(const Finding& f) {
  std::string s;
  for (const PartyStanding& p : f.evaluation.verdict.parties) {
    if (p.standing == Standing::right || p.standing == Standing::not_applicable) continue;
    if (!s.empty()) s += "; ";
    s += p.party + " " + std::string(to_string(p.standing)) + ": " + p.why;
  }
  return s;
}

void print_findings(const CampaignResult& r, int max_print) {
  std::map<std::pair<QueryKind, CaseClass>, int> printed;
  std::map<std::pair<QueryKind, CaseClass>, int> skipped;
  for (const Finding& f : r.findings) {
    const auto key = std::pair{f.kind, f.evaluation.verdict.cls};
    if (printed[key] >= max_print) {
      ++skipped[key];
      continue;
    }
    ++printed[key];
    std::printf("\n%s %s case %llu: %s%s\n  inputs: %s\n", std::string(to_string(f.evaluation.verdict.cls)).c_str(),
                std::string(name(f.kind)).c_str(), static_cast<unsigned long long>(f.case_index),
                f.crash.empty() ? "" : (f.crash + "; ").c_str(), summary_of(f).c_str(),
                input_to_json(f.input).dump().c_str());
  }
  for (const auto& [key, n] : skipped) {
    std::printf("\n(%d more %s findings on %s not printed; --json lists them all)\n", n,
                std::string(to_string(key.second)).c_str(), std::string(name(key.first)).c_str());
  }
}

Json result_json(const CampaignResult& r) {
  Json queries = Json::object();
  for (const auto& [kind, t] : r.tallies) {
    Json q = {{"cases", t.cases}};
    for (CaseClass c : kAllClasses) q[std::string(to_string(c))] = t.count(c);
    q["cases_per_second"] = cases_per_second(t, r.workers);
    queries[std::string(name(kind))] = q;
  }
  Json findings = Json::array();
  for (const Finding& f : r.findings) {
    findings.push_back({{"query", name(f.kind)},
                        {"case", f.case_index},
                        {"class", to_string(f.evaluation.verdict.cls)},
                        {"what", f.crash.empty() ? summary_of(f) : f.crash + "; " + summary_of(f)},
                        {"inputs", input_to_json(f.input)}});
  }
  return {{"seed", r.seed},       {"seconds", r.seconds},  {"workers", r.workers},
          {"interrupted", r.interrupted}, {"queries", queries}, {"findings", findings}};
}

int run(const CampaignArgs& args) {
  CampaignOptions options;
  for (const std::string& q : args.queries) {
    const auto kind = query_kind_named(q);
    if (!kind) {
      std::fprintf(stderr, "crosscheck campaign: unknown query \"%s\"\n", q.c_str());
      return kExitBadInput;
    }
    options.kinds.push_back(*kind);
  }
  if (options.kinds.empty()) options.kinds.assign(kAllQueryKinds.begin(), kAllQueryKinds.end());
  options.seconds = args.seconds;
  options.seed = args.seed;
  options.workers = std::max(1, args.workers);
  options.case_timeout_seconds = args.timeout;
  options.out_of_contract_percent = args.out_of_contract;
  const bool tty = isatty(STDERR_FILENO) != 0;
  int since_line = 0;
  options.progress = [tty, &since_line](const std::string& line) {
    if (tty) {
      std::fprintf(stderr, "\r%s   ", line.c_str());
    } else if (++since_line % 10 == 1) {
      std::fprintf(stderr, "%s\n", line.c_str());
    }
  };
  std::printf("crosscheck campaign: seed %llu, %g s, %d workers, %zu query kinds\n",
              static_cast<unsigned long long>(options.seed), options.seconds, options.workers, options.kinds.size());
  std::fflush(stdout);
  const CampaignResult r = run_campaign(options, make_oracles());
  if (tty) std::fprintf(stderr, "\n");
  print_findings(r, args.max_print);
  print_table(r);
  if (r.interrupted) std::printf("\n(interrupted after %.1f s)\n", r.seconds);
  if (!args.json.empty()) {
    std::ofstream out(args.json);
    out << result_json(r).dump(2) << "\n";
    if (!out) {
      std::fprintf(stderr, "crosscheck campaign: cannot write %s\n", args.json.c_str());
      return kExitBadInput;
    }
  }
  std::uint64_t bugs = 0;
  for (const auto& [kind, t] : r.tallies) bugs += t.count(CaseClass::impl_bug);
  return bugs > 0 ? kExitFound : 0;
}

}  // namespace

void add_campaign_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CampaignArgs>();
  auto* cmd = app.add_subcommand("campaign", "Run a differential campaign: library vs FCL/libccd vs exact arithmetic");
  cmd->add_option("--query", args->queries, "A query kind to run (repeatable; default: all)");
  cmd->add_option("--seconds", args->seconds, "Time budget in seconds")->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the case generator")->capture_default_str();
  cmd->add_option("--workers", args->workers, "Worker processes")->capture_default_str();
  cmd->add_option("--timeout", args->timeout, "Seconds after which a case counts as a hang")->capture_default_str();
  cmd->add_option("--out-of-contract", args->out_of_contract, "Percent of cases generated out of contract")
      ->capture_default_str();
  cmd->add_option("--json", args->json, "Write the summary and every finding to this JSON file");
  cmd->add_option("--max-print", args->max_print, "Findings printed per query and class")->capture_default_str();
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
