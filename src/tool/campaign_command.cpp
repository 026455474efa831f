// crosscheck campaign: the main job. Runs every query kind (or those named) for a time budget
// and prints a table of classes per kind; each impl_bug, oracle_defect and oracle_crash is
// printed with its exact inputs.
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <thread>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <system_error>

#include "harness/processes/campaign.h"
#include "harness/processes/child.h"
#include "harness/judging/median.h"
#include "harness/formats/mesh_files.h"
#include "harness/formats/input_json.h"
#include "harness/shrinking/shrink.h"
#include "harness/shrinking/signature.h"
#include "tool/cases.h"
#include "tool/commands.h"
#include "tool/flag_checks.h"
#include "tool/oracles.h"

namespace cc::tool {
namespace {

using harness::median;

using namespace harness;

// Worker processes at most: more than a machine has cores only slows a campaign down, and an
// unbounded count is a fork bomb.
constexpr int kMaxWorkers = 256;

struct CampaignArgs {
  std::vector<std::string> queries;
  double seconds = 60;
  std::uint64_t seed = 1;
  int workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  double timeout = 20;
  int out_of_contract = 10;
  std::string json;
  int max_print = 20;
  std::string corpora = "corpora";
  std::string out = "corpora/new";
  int max_new = 30;
  int per_key = 1;
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
  if (!f.evaluation.exact.decided && !f.evaluation.exact.note.empty()) {
    s += (s.empty() ? "" : "; ") + std::string("exact reference: ") + f.evaluation.exact.note;
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

struct Stored {
  int written = 0, known = 0, failed = 0, grouped = 0;
  std::vector<int> complex_before, complex_after;  // values not small integers or halves
};

// Shrinks one finding and writes it as a new case file, in a child process: a shrinking step
// may call FCL on inputs that crash it. Exit 0: written; 3: already stored; else failed.
int store_one(const Finding& f, const CampaignArgs& args, const std::vector<std::string>& known, int report) {
  const auto is_known = [&](const Input& in) {
    return std::binary_search(known.begin(), known.end(), case_file_name(in));
  };
  if (is_known(f.input)) return 3;
  Input input = f.input;
  Evaluation e = f.evaluation;
  if (f.crash.empty()) {
    const ShrinkResult r = shrink(f.input, f.evaluation, evaluate_with_oracles, 3000, 20, args.corpora);
    input = r.input;
    e = r.evaluation;
  }
  const std::string counts = std::to_string(complex_values(f.input)) + " " + std::to_string(complex_values(input)) + "\n";
  if (!harness::write_all(report, counts)) return 1;
  if (is_known(input)) return 3;
  const Provenance provenance{"campaign", std::nullopt, f.case_index, "seed " + std::to_string(args.seed)};
  Case c = case_of(input, e, provenance, "untriaged: " + signature_of(f.kind, e) + (f.crash.empty() ? "" : "; " + f.crash));
  c.provenance.seed = args.seed;
  const auto path = std::filesystem::path(args.out) / std::string(name(f.kind)) / case_file_name(input);
  try {
    return write_new_case_file(path, c) ? 0 : 3;
  } catch (const CaseFileError&) {
    return 1;
  }
}

Stored store_findings(const CampaignResult& r, const CampaignArgs& args) {
  Stored s;
  std::vector<std::string> known = stored_case_names(args.corpora);
  std::map<std::string, int> per_key;
  for (const Finding& f : r.findings) {
    if (s.written >= args.max_new) break;
    const std::string key = finding_key(f.input, f.evaluation) + (f.crash.empty() ? "" : " crash");
    if (per_key[key]++ >= args.per_key) {
      ++s.grouped;
      continue;
    }
    harness::ChildEnd child;
    try {
      child = harness::run_in_child([&](int out) { return store_one(f, args, known, out); }, 120);
    } catch (const std::system_error&) {
      break;
    }
    int before = 0, after = 0;
    if (std::sscanf(child.output.c_str(), "%d %d", &before, &after) == 2) {
      s.complex_before.push_back(before);
      s.complex_after.push_back(after);
    }
    const int code = child.status;
    if (code == 0) {
      ++s.written;
      known = stored_case_names(args.corpora);  // the new file may be under the corpus root
    } else if (code == 3) {
      ++s.known;
    } else {
      ++s.failed;
    }
  }
  return s;
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
  options.mesh_folder = mesh_folder(args.corpora);
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
  if (args.max_new > 0 && !r.findings.empty()) {
    const Stored s = store_findings(r, args);
    std::printf("\n%d new case file%s written to %s (shrunk; one per kind of finding), %d already stored under %s, "
                "%d findings grouped with others%s\n",
                s.written, s.written == 1 ? "" : "s", args.out.c_str(), s.known, args.corpora.c_str(), s.grouped,
                s.failed ? (", " + std::to_string(s.failed) + " could not be stored").c_str() : "");
    if (!s.complex_before.empty()) {
      std::printf("shrinking: median number of values that are not small integers or halves, %g before and %g "
                  "after (over %zu findings)\n",
                  median(s.complex_before), median(s.complex_after), s.complex_before.size());
    }
  }
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
  cmd->add_option("--query", args->queries, "A query kind to run (repeatable; default: all)")->check(query_kind_name());
  cmd->add_option("--seconds", args->seconds, "Time budget in seconds")->capture_default_str()->check(finite_above(0, 1e6));
  cmd->add_option("--seed", args->seed, "Seed of the case generator")->capture_default_str()->check(seed_value());
  cmd->add_option("--workers", args->workers, "Worker processes")->capture_default_str()->check(whole_in(1, kMaxWorkers));
  cmd->add_option("--timeout", args->timeout, "Seconds after which a case counts as a hang")
      ->capture_default_str()
      ->check(finite_above(0, 86400));
  cmd->add_option("--out-of-contract", args->out_of_contract, "Percent of cases generated out of contract")
      ->capture_default_str()
      ->check(whole_in(0, 100));
  cmd->add_option("--json", args->json, "Write the summary and every finding to this JSON file")->check(writable_file());
  cmd->add_option("--max-print", args->max_print, "Findings printed per query and class")
      ->capture_default_str()
      ->check(whole_in(0, 1000000));
  cmd->add_option("--out", args->out, "Where new findings are written as shrunk case files")->capture_default_str();
  cmd->add_option("--corpora", args->corpora, "Cases stored anywhere under this root are not written again")
      ->capture_default_str()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--max-new", args->max_new, "New case files written at most (0: none)")
      ->capture_default_str()
      ->check(whole_in(0, 1000000));
  cmd->add_option("--per-kind-of-finding", args->per_key,
                  "Cases written per kind of finding (same class, parties, features and margin decade)")
      ->capture_default_str()
      ->check(whole_in(1, 1000000));
  // --out is checked up front even when left at its default: findings go there after the budget.
  cmd->callback([args, &exit_code] {
    if (const std::string why = args->max_new > 0 ? unwritable_folder(args->out) : ""; !why.empty()) {
      std::fprintf(stderr, "crosscheck campaign: --out: %s\n", why.c_str());
      exit_code = kExitBadInput;
      return;
    }
    exit_code = run(*args);
  });
}

}  // namespace cc::tool
