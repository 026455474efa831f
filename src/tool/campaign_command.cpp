// crosscheck campaign: the main job. Runs every query kind (or those named) within a time budget,
// stores what it finds as new case files (shrunk while the budget lasts), and prints one line per
// finding with its case file and a table of classes per kind. SIGINT or SIGTERM stops it and
// keeps everything; a second one stores the rest as found at once.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <thread>

#include <algorithm>
#include <numeric>
#include <chrono>
#include <cerrno>
#include <csignal>
#include <cmath>
#include <cstring>
#include <ctime>
#include <sstream>
#include <system_error>

#include "harness/formats/write_all.h"
#include "harness/processes/campaign.h"
#include "harness/processes/child.h"
#include "harness/processes/interrupts.h"
#include "harness/judging/median.h"
#include "harness/formats/mesh_files.h"
#include "harness/formats/input_json.h"
#include "harness/shrinking/shrink.h"
#include "harness/judging/disagreement.h"
#include "harness/shrinking/signature.h"
#include "harness/model/subject.h"
#include "tool/output_file.h"
#include "tool/cases.h"
#include "tool/child_process.h"
#include "tool/commands.h"
#include "tool/flag_checks.h"
#include "tool/history.h"
#include "tool/oracles.h"
#include "tool/run_context.h"
#include "tool/subject_option.h"

namespace cc::tool {
namespace {

using harness::median;

using namespace harness;

// Worker processes at most: more than a machine has cores only slows a campaign down, and an
// unbounded count is a fork bomb.
constexpr int kMaxWorkers = 256;

// The share of --seconds that shrinking the findings gets (the cases get the rest); after an
// interrupt it gets at most kGraceAfterInterrupt more; a finding is shrunk for its share of
// what is left, at least kMinShrinkSeconds (else it is stored as found), and its child gets
// kShrinkSlackSeconds more before it is killed.
constexpr double kShrinkShare = 0.25;
constexpr double kGraceAfterInterrupt = 3;
constexpr double kMinShrinkSeconds = 0.1;
constexpr double kShrinkSlackSeconds = 2;
// A finding stored as found is asked again in a fresh process (in milliseconds, unless a party
// hangs there) for its share of the time left, or at least this long.
constexpr double kMinAskAgainSeconds = 1;

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
  std::string subject;
  std::string history;
};

void print_table(const CampaignResult& r) {
  std::printf("\n%-*s %10s %10s %9s %14s %13s %9s %16s %10s %10s\n", harness::longest_kind_name(), "query", "cases", "agree",
              "impl_bug", "oracle_defect", "oracle_crash", "boundary", "out_of_contract", "undecided", "cases/s");
  for (const auto& [kind, t] : r.tallies) {
    std::printf("%-*s %10llu %10llu %9llu %14llu %13llu %9llu %16llu %10llu %10.0f\n",
                harness::longest_kind_name(), std::string(name(kind)).c_str(), static_cast<unsigned long long>(t.cases),
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
  std::string s = f.crash;
  for (const PartyStanding& p : f.evaluation.verdict.parties) {
    if (p.standing == Standing::right || p.standing == Standing::not_applicable) continue;
    if (p.party == "library" && !f.crash.empty() && p.why == f.crash) continue;
    if (!s.empty()) s += "; ";
    s += p.party + " " + std::string(to_string(p.standing)) + ": " + p.why;
  }
  if (!f.evaluation.exact.decided && !f.evaluation.exact.note.empty()) {
    s += (s.empty() ? "" : "; ") + std::string("exact reference: ") + f.evaluation.exact.note;
  }
  return s;
}

// A line for the terminal: long texts (a mesh's inputs, a long reason) keep their start.
std::string elided(const std::string& text, std::size_t limit) {
  if (text.size() <= limit) return text;
  return text.substr(0, limit) + "... (" + std::to_string(text.size() - limit) + " more characters)";
}

// What became of one finding when the campaign stored what it found.
struct Storage {
  enum class How { written, known, grouped, over_cap, failed } how = How::over_cap;
  std::string path;        // its case file (written), or that of the finding it is grouped with
  std::string not_shrunk;  // written as found, and why
  std::string failure;     // why it could not be stored
  std::size_t group = 0;   // the findings of its kind of finding (same key), itself included
  std::size_t like = 0;    // grouped: the finding of its kind that was chosen to be stored
  std::string key;         // its kind of finding (finding_key, and " crash" for a crash)
};

std::string_view how_name(Storage::How how) {
  switch (how) {
    case Storage::How::written: return "written";
    case Storage::How::known: return "already stored";
    case Storage::How::grouped: return "grouped";
    case Storage::How::over_cap: return "not stored (--max-new)";
    case Storage::How::failed: return "could not be stored";
  }
  return "?";
}

struct Stored {
  std::vector<Storage> of;  // per finding, in the order of CampaignResult::findings
  int written = 0, shrunk = 0, known = 0, failed = 0, grouped = 0, over_cap = 0;
  std::vector<int> complex_before, complex_after;  // values not small integers or halves
};

// The case file of a finding, with `e` as its answers, asked again here first for at most
// `ask_again_seconds` (0: not at all), as every command asks a case (a worker answers in a
// process with a history, replay in a fresh one), unless the finding is a hang. When a party
// answered differently here, the note says what the worker saw; when the time ran out, a
// second interrupt came or no process could be started first, the worker's answers are stored,
// and the note says why.
Case stored_case(const Finding& f, const Input& input, const Evaluation& e, const CampaignArgs& args,
                 std::string not_shrunk, double ask_again_seconds) {
  const Provenance provenance{"campaign", args.seed, f.case_index, "seed " + std::to_string(args.seed)};
  const harness::Subject* subject = harness::subject_under_test();
  // A death in the second opinions is asked again too (one in a fresh process is the same
  // record; a worker may die of what earlier cases left in it), but a hang is not (it would cost
  // the whole time limit again), nor a death in the exact reference, which would run its code
  // again in this process, nor one in the library, stored as its worker saw it.
  const bool again = ask_again_seconds > 0 && !is_time_out(f.crash) &&
                     (f.crash.empty() || f.died_in == harness::DiedIn::second_opinions);
  std::optional<Evaluation> fresh;
  std::string not_asked;  // why it was not asked again, when it should have been
  if (again && interrupts() > 1) {
    not_asked = "interrupted twice";
  } else if (again) {
    try {
      fresh = evaluate_again_within(input, ask_again_seconds, [] { return interrupts() > 1; });
      if (!fresh) not_asked = interrupts() > 1 ? "interrupted twice" : "no time left";
    } catch (const std::system_error& error) {
      not_asked = std::string("no process could be started: ") + error.what();
    }
  }
  const Evaluation& stored = fresh ? *fresh : e;
  std::string note = "untriaged: " + (subject != nullptr ? "subject " + subject->path() + ": " : std::string()) +
                     signature_of(f.kind, stored) + (f.crash.empty() ? "" : "; " + f.crash);
  if (signature_of(f.kind, stored) != signature_of(f.kind, e)) {
    note += "; its worker saw " + signature_of(f.kind, e) + " (a party answers differently in a fresh process)";
  }
  if (!not_asked.empty()) note += "; as its worker answered it, not asked again in a fresh process (" + not_asked + ")";
  Case c = case_of(input, stored, provenance, note);
  c.not_shrunk = std::move(not_shrunk);
  return c;
}

// Where a case file of this name is stored under the corpus root (the first found), or its name.
std::string stored_case_path(const std::filesystem::path& root, const std::string& file_name) {
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(root, ec); !ec && it != decltype(it)(); it.increment(ec)) {
    if (it->path().filename() == file_name) return it->path().string();
  }
  return file_name;
}

std::filesystem::path case_path(const Finding& f, const Input& input, const CampaignArgs& args) {
  return std::filesystem::path(args.out) / std::string(name(f.kind)) / case_file_name(input);
}

// Shrinks one finding for at most `seconds` and writes it as a new case file, in a child
// process: a shrinking step may call FCL on inputs that crash it. Reports on `report` the
// measure of shrinking before and after, then "W <path>" (written), "K" (already stored) or
// "F <reason>". FCL's and Eigen's messages while shrinking are dropped (stderr: /dev/null).
// SIGTERM (the supervisor's stop) ends it, but not while it writes the file and reports it.
int shrink_and_store(const Finding& f, const CampaignArgs& args, const std::vector<std::string>& known, double seconds,
                     int report) {
  if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) ::dup2(null, STDERR_FILENO);
  std::signal(SIGINT, SIG_IGN);  // the terminal's Ctrl-C is the supervisor's to judge
  std::signal(SIGTERM, SIG_DFL);
  const double started = monotonic_seconds();
  const ShrinkResult r = shrink(f.input, f.evaluation, evaluate_surviving_crashes, 3000, seconds, args.corpora);
  sigset_t term;
  sigemptyset(&term);
  sigaddset(&term, SIGTERM);
  sigprocmask(SIG_BLOCK, &term, nullptr);
  std::string line = std::to_string(complex_values(f.input)) + " " + std::to_string(complex_values(r.input)) + "\n";
  if (std::binary_search(known.begin(), known.end(), case_file_name(r.input))) {
    line += "K " + stored_case_path(args.corpora, case_file_name(r.input)) + "\n";
  } else {
    try {
      // Shrinking asked each candidate it kept as every command does; none kept: the worker's answers.
      // (Asked again within the time this child has left before it is killed.)
      const double left = std::max(0.0, started + seconds - monotonic_seconds()) + kShrinkSlackSeconds / 2;
      Case c = stored_case(f, r.input, r.evaluation, args, "", r.accepted == 0 ? left : 0);
      if (r.out_of_time) c.note += "; shrinking ran out of time (it may shrink further)";
      const auto target = case_path(f, r.input, args);
      const auto path = write_new_case_file(target, c);
      line += path ? "W " + path->string() + "\n" : "K " + target.string() + "\n";
    } catch (const CaseFileError& e) {
      line += std::string("F ") + e.what() + "\n";
    }
  }
  return harness::write_all(report, line) ? 0 : 1;
}

// Writes a finding as found, here, asked again as every command asks it within `share` seconds
// (its share of the time left), or at least kMinAskAgainSeconds.
void store_as_found(const Finding& f, const CampaignArgs& args, const std::string& why, double share, Storage& s) {
  try {
    const auto target = case_path(f, f.input, args);
    const double ask_again = std::max(share, kMinAskAgainSeconds);
    const auto path = write_new_case_file(target, stored_case(f, f.input, f.evaluation, args, why, ask_again));
    s.how = path ? Storage::How::written : Storage::How::known;
    s.path = path ? path->string() : target.string();
    if (path) s.not_shrunk = why;
  } catch (const CaseFileError& e) {
    s.how = Storage::How::failed;
    s.failure = e.what();
  }
}

// The findings to write, one per kind of finding (at most --per-kind-of-finding each), taken
// in turns from every query kind and class so that the cap (--max-new) is shared by all.
std::vector<std::size_t> chosen_findings(const CampaignResult& r, const CampaignArgs& args, Stored& stored,
                                         std::map<std::string, std::size_t>& first_of_key) {
  std::map<std::string, int> per_key;
  std::map<std::pair<QueryKind, CaseClass>, std::vector<std::size_t>> queues;
  for (std::size_t i = 0; i < r.findings.size(); ++i) {
    const Finding& f = r.findings[i];
    const std::string key = finding_key(f.input, f.evaluation) + (f.crash.empty() ? "" : " crash");
    first_of_key.try_emplace(key, i);
    stored.of[i].key = key;
    ++stored.of[first_of_key[key]].group;
    if (per_key[key]++ >= args.per_key) {
      stored.of[i].how = Storage::How::grouped;
      stored.of[i].like = first_of_key[key];
      continue;
    }
    queues[{f.kind, f.evaluation.verdict.cls}].push_back(i);
  }
  // The library's findings (impl_bug: the subject's, with --subject) take the cap first, then
  // the other parties' (oracle_defect, out_of_contract, ...), each in turns over kind and class.
  std::vector<std::size_t> chosen;
  for (const bool library : {true, false}) {
    for (std::size_t turn = 0; static_cast<int>(chosen.size()) < args.max_new; ++turn) {
      bool any = false;
      for (auto& [key, queue] : queues) {
        if ((key.second == CaseClass::impl_bug) != library) continue;
        if (turn < queue.size() && static_cast<int>(chosen.size()) < args.max_new) {
          chosen.push_back(queue[turn]);
          any = true;
        }
      }
      if (!any) break;
    }
  }
  return chosen;
}

// Stores the findings by `deadline` (seconds on the monotonic clock): each is shrunk for its
// share of the time left, or written as found (and marked so) when none is left, when the run
// was interrupted and the grace after it is over, or when a second SIGINT or SIGTERM arrives.
Stored store_findings(const CampaignResult& r, const CampaignArgs& args, double deadline) {
  Stored s;
  s.of.resize(r.findings.size());
  std::map<std::string, std::size_t> first_of_key;
  const std::vector<std::size_t> chosen = chosen_findings(r, args, s, first_of_key);
  // A subject's findings are its own: the cases stored of crosscheck's library are not theirs.
  std::vector<std::string> known =
      harness::subject_under_test() == nullptr ? stored_case_names(args.corpora) : std::vector<std::string>{};
  const bool tty = isatty(STDERR_FILENO) != 0;
  for (std::size_t n = 0; n < chosen.size(); ++n) {
    const Finding& f = r.findings[chosen[n]];
    Storage& storage = s.of[chosen[n]];
    if (std::binary_search(known.begin(), known.end(), case_file_name(f.input))) {
      storage.how = Storage::How::known;
      storage.path = stored_case_path(args.corpora, case_file_name(f.input));
      continue;
    }
    if (interrupts() > 0) deadline = std::min(deadline, monotonic_seconds() + kGraceAfterInterrupt);
    // An equal share of the time left, but at least kMinShrinkSeconds while that is left: when
    // the time is short the first findings are shrunk, the rest stored as found.
    const double left = deadline - monotonic_seconds();
    const double share = std::max(left / static_cast<double>(chosen.size() - n), std::min(left, kMinShrinkSeconds));
    std::fprintf(stderr, tty ? "\r[storing %zu/%zu] %-14s case %llu, %.1f s left   " : "[storing %zu/%zu] %s case %llu, %.1f s left\n",
                 n + 1, chosen.size(), std::string(name(f.kind)).c_str(), static_cast<unsigned long long>(f.case_index),
                 std::max(0.0, left));
    const bool crashed = !f.crash.empty();  // shrinking would crash it again
    if (interrupts() > 1 || share < kMinShrinkSeconds || crashed) {
      store_as_found(f, args,
                     crashed ? "a crash or hang is stored as found"
                     : interrupts() > 1 ? "interrupted twice"
                     : interrupts() > 0 ? "interrupted" : "no time left in --seconds",
                     share, storage);
    } else {
      harness::ChildEnd child;
      try {
        // In a group of its own: a stop reaches the children it asks the parties in.
        child = harness::run_in_child([&](int out) { return shrink_and_store(f, args, known, share, out); },
                                      share + kShrinkSlackSeconds, [] { return interrupts() > 1; },
                                      harness::ChildGroup::own);
      } catch (const std::system_error& e) {  // no process to shrink in: stored as found
        store_as_found(f, args, std::string("cannot shrink: ") + e.what(), share, storage);
        continue;
      }
      std::istringstream report(child.output);
      int before = 0, after = 0;
      std::string tag, rest;
      if (report >> before >> after >> tag) {
        std::getline(report >> std::ws, rest);
        s.complex_before.push_back(before);
        s.complex_after.push_back(after);
      }
      // Its report counts once given, even if the child was stopped after it: the file is there.
      if (tag == "W" || tag == "K") {
        storage.how = tag == "W" ? Storage::How::written : Storage::How::known;
        storage.path = rest;
      } else if (tag == "F") {
        storage.how = Storage::How::failed;
        storage.failure = rest;
      } else {  // the shrinking child crashed, ran out of time or was stopped first: as found
        store_as_found(f, args, child.stopped ? "interrupted twice" : "shrinking " + child.what(), share, storage);
      }
    }
    if (storage.how == Storage::How::written) known = stored_case_names(args.corpora);  // it may be under the root
  }
  if (tty && !chosen.empty()) std::fprintf(stderr, "\n");
  for (Storage& storage : s.of) {
    switch (storage.how) {
      case Storage::How::written:
        ++s.written;
        s.shrunk += storage.not_shrunk.empty();
        break;
      case Storage::How::known: ++s.known; break;
      case Storage::How::failed: ++s.failed; break;
      case Storage::How::over_cap: ++s.over_cap; break;
      case Storage::How::grouped: {
        ++s.grouped;
        storage.path = s.of[storage.like].path;  // empty when that one was not stored
        break;
      }
    }
  }
  return s;
}

// One line per finding stored (or that could not be), at most --max-print per query and class,
// each naming its case file (the inputs are there and in --json); one line counts the rest.
void print_findings(const CampaignResult& r, const Stored& s, int max_print) {
  std::map<std::pair<QueryKind, CaseClass>, int> printed, unprinted;
  // The library's findings (impl_bug) are printed first, then the other parties'.
  std::vector<std::size_t> order(r.findings.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_partition(order.begin(), order.end(),
                        [&](std::size_t i) { return r.findings[i].evaluation.verdict.cls == CaseClass::impl_bug; });
  for (const std::size_t i : order) {
    const Finding& f = r.findings[i];
    const Storage& storage = s.of[i];
    if (storage.how == Storage::How::grouped) continue;
    const auto key = std::pair{f.kind, f.evaluation.verdict.cls};
    if (storage.how == Storage::How::over_cap || printed[key] >= max_print) {
      ++unprinted[key];
      continue;
    }
    ++printed[key];
    std::string where;
    switch (storage.how) {
      case Storage::How::written:
        where = storage.path + (storage.not_shrunk.empty() ? "" : " (not shrunk: " + storage.not_shrunk + ")");
        break;
      case Storage::How::failed: where = "NOT STORED: " + storage.failure; break;
      default: where = "already stored (" + (storage.path.empty() ? case_file_name(f.input) : storage.path) + ")";
    }
    std::printf("%s %s case %llu%s: %s\n  -> %s\n", std::string(to_string(f.evaluation.verdict.cls)).c_str(),
                std::string(name(f.kind)).c_str(), static_cast<unsigned long long>(f.case_index),
                storage.group > 1 ? (" (and " + std::to_string(storage.group - 1) + " like it)").c_str() : "",
                elided(summary_of(f), 150).c_str(), where.c_str());
  }
  if (unprinted.empty()) return;
  std::string rest;
  int kinds = 0;
  for (const auto& [key, n] : unprinted) {
    kinds += n;
    rest += (rest.empty() ? "" : ", ") + std::to_string(n) + " " + std::string(to_string(key.second)) + " on " +
            std::string(name(key.first));
  }
  std::printf("(%d more kinds of finding not printed or not stored: %s; --json lists every finding)\n", kinds,
              elided(rest, 240).c_str());
}

Json result_json(const CampaignResult& r, const Stored& s, int signal) {
  Json queries = Json::object();
  for (const auto& [kind, t] : r.tallies) {
    Json q = {{"cases", t.cases}};
    for (CaseClass c : kAllClasses) q[std::string(to_string(c))] = t.count(c);
    q["cases_per_second"] = cases_per_second(t, r.workers);
    queries[std::string(name(kind))] = q;
  }
  Json findings = Json::array();
  for (std::size_t i = 0; i < r.findings.size(); ++i) {
    const Finding& f = r.findings[i];
    const Storage& storage = s.of[i];
    Json j = {{"query", name(f.kind)},
              {"case", f.case_index},
              {"class", to_string(f.evaluation.verdict.cls)},
              {"what", summary_of(f)},
              {"stored", how_name(storage.how)},
              {"group", storage.key}};
    // The parties not plainly right, with their standing; and the exact margin, where finite.
    Json parties = Json::object();
    for (const harness::PartyStanding& p : f.evaluation.verdict.parties) {
      if (p.standing == harness::Standing::right || p.standing == harness::Standing::not_applicable) continue;
      parties[p.party] = to_string(p.standing);
    }
    j["parties"] = parties;
    if (const auto d = harness::disagreement_of(f.kind, f.evaluation)) j["disagreement"] = group_name(f.kind, d->what);
    if (std::isfinite(f.evaluation.exact.margin)) j["margin"] = f.evaluation.exact.margin;
    // A finding grouped with a stored one is like it, and its inputs follow from the seed and
    // its case number (harness::campaign_case): they are not spelled out again.
    if (storage.how != Storage::How::grouped || storage.path.empty()) j["inputs"] = input_to_json(f.input);
    if (!storage.path.empty()) j["case_file"] = storage.path;
    if (!storage.not_shrunk.empty()) j["not_shrunk"] = storage.not_shrunk;
    if (!storage.failure.empty()) j["failure"] = storage.failure;
    findings.push_back(j);
  }
  const Json stored = {{"written", s.written}, {"shrunk", s.shrunk},     {"already_stored", s.known},
                       {"grouped", s.grouped}, {"over_cap", s.over_cap}, {"failed", s.failed}};
  Json j = {{"seed", r.seed},         {"seconds", r.seconds}, {"workers", r.workers},
            {"interrupted", r.interrupted}, {"queries", queries}, {"findings", findings},
            {"stored", stored},       {"problems", r.problems}, {"cases_writing_to_stderr", r.noisy_cases},
            {"cases_asked_again", r.asked_again}};
  if (signal != 0) j["signal"] = signal;
  return j;
}

int run(const CampaignArgs& args) {
  count_interrupts();  // from here on SIGINT and SIGTERM stop the run and keep what it found
  const double started = monotonic_seconds();
  const std::time_t started_at = std::time(nullptr);
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
  put_subject_under_test(args.subject, args.timeout);
  options.kinds = answered_kinds(options.kinds, "campaign");
  if (options.kinds.empty()) {
    std::fprintf(stderr, "crosscheck campaign: --subject: it answers none of the query kinds asked\n");
    return kExitBadInput;
  }
  // --seconds bounds the whole run: cases get their share, shrinking what they found the rest.
  options.seconds = args.max_new > 0 ? args.seconds * (1 - kShrinkShare) : args.seconds;
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
  std::printf("crosscheck campaign: seed %llu, %g s (%g s of cases), %d workers, %zu query kinds\n",
              static_cast<unsigned long long>(options.seed), args.seconds, options.seconds, options.workers,
              options.kinds.size());
  std::fflush(stdout);
  const CampaignResult r = run_campaign(options, make_oracles());
  if (tty) std::fprintf(stderr, "\n");
  if (r.interrupted) {
    std::fprintf(stderr, "crosscheck campaign: interrupted: storing the %zu findings%s\n", r.findings.size(),
                 args.max_new > 0 ? " (interrupt again to store them as found, unshrunk, at once)" : "");
  }
  const Stored s = store_findings(r, args, started + args.seconds);
  std::printf("\n");
  print_findings(r, s, args.max_print);
  print_table(r);
  for (const std::string& problem : r.problems) std::printf("PROBLEM: %s\n", problem.c_str());
  if (r.noisy_cases > 0) {
    std::printf("\n%llu cases wrote to standard output or error (a peer's messages, or the subject's, captured); the first, %s\n",
                static_cast<unsigned long long>(r.noisy_cases), elided(r.first_noise, 160).c_str());
  }
  if (r.asked_again > 0) {
    std::printf("\n%llu case%s asked again: a worker was killed in it by another process (an interruption, not a finding)\n",
                static_cast<unsigned long long>(r.asked_again), r.asked_again == 1 ? " was" : "s were");
  }
  if (r.interrupted) std::printf("\n(interrupted after %.1f s)\n", r.seconds);
  if (args.max_new > 0 && !r.findings.empty()) {
    std::printf("\n%d new case file%s written to %s (%d shrunk, %d as found), %d already stored (under %s or %s), "
                "%d findings grouped with others, %d over --max-new %d%s\n",
                s.written, s.written == 1 ? "" : "s", args.out.c_str(), s.shrunk, s.written - s.shrunk, s.known,
                args.corpora.c_str(), args.out.c_str(), s.grouped, s.over_cap, args.max_new,
                s.failed ? (", " + std::to_string(s.failed) + " COULD NOT BE STORED (see above)").c_str() : "");
    if (s.over_cap > 0) {
      std::printf("(--max-new and --max-print go to the library's findings, impl_bug%s, before other parties' "
                  "oracle_defect and out_of_contract cases)\n",
                  harness::subject_under_test() != nullptr ? ": the subject's" : "");
    }
    if (!s.complex_before.empty()) {
      std::printf("shrinking: median number of values that are not small integers or halves, %g before and %g "
                  "after (over %zu findings)\n",
                  median(s.complex_before), median(s.complex_after), s.complex_before.size());
    }
  }
  int code = 0;
  const Json result = result_json(r, s, r.interrupted ? last_interrupt() : 0);
  if (!args.json.empty()) {
    const std::string why = write_output_file(args.json, result.dump(2) + "\n");
    if (!why.empty()) {
      std::fprintf(stderr, "crosscheck campaign: %s\n", why.c_str());
      code = kExitIncomplete;
    }
  }
  if (!args.history.empty()) {
    const double whole = monotonic_seconds() - started;
    Json record = run_record("campaign", started_at, whole, args.subject);
    record.update(result);  // its "seconds" are the cases' share
    record["seconds_of_cases"] = r.seconds;
    record["seconds"] = whole;
    try {
      std::printf("history: %s\n", add_to_history(args.history, record).c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "crosscheck campaign: --history: %s\n", e.what());
      code = kExitIncomplete;
    }
  }
  std::fflush(stdout);
  if (s.failed > 0 || !r.problems.empty()) return kExitIncomplete;
  if (code != 0) return code;
  if (r.interrupted) return 128 + last_interrupt();
  std::uint64_t bugs = 0;
  for (const auto& [kind, t] : r.tallies) bugs += t.count(CaseClass::impl_bug);
  return bugs > 0 ? kExitFound : 0;
}

}  // namespace

void add_campaign_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CampaignArgs>();
  auto* cmd = app.add_subcommand("campaign", "Run a differential campaign: the library (or a subject) vs FCL/libccd, Bullet and ODE vs exact arithmetic");
  cmd->add_option("--query", args->queries, "A query kind to run (repeatable; default: all)")->check(query_kind_name());
  cmd->add_option("--seconds", args->seconds, "Time budget in seconds")->capture_default_str()->check(finite_above(0, 1e6));
  cmd->add_option("--seed", args->seed, "Seed of the case generator")->capture_default_str()->check(seed_value());
  cmd->add_option("--workers", args->workers, "Worker processes")->capture_default_str()->check(whole_in(1, kMaxWorkers));
  // At least a second: a shorter limit calls a case's honest work (a mesh, a slow peer) a hang.
  cmd->add_option("--timeout", args->timeout, "Seconds after which a case counts as a hang (at least 1)")
      ->capture_default_str()
      ->check(finite_in(1, 86400));
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
  cmd->add_option("--history", args->history, "Add the run's record to this history folder (a new file, for crosscheck report)")
      ->check(writable_folder());
  add_subject_option(cmd, args->subject);
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
