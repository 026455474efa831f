// crosscheck mutate: the harness checks itself. Each mutant of the catalogue (a small plausible
// bug planted in the library) is applied to a scratch copy of the tree, built incrementally, and
// put to ctest's labels (stop on the first failure; a timeout counts as caught) and then to a
// short campaign on its query kind. The report says which check caught each mutant and after how
// long, or that it survived, and the score.
#include <algorithm>
#include <cstdlib>
#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <thread>
#include <unistd.h>

#include "tool/child_process.h"
#include "tool/ctest_log.h"
#include "tool/commands.h"
#include "tool/flag_checks.h"
#include "tool/mutant_catalogue.h"
#include "tool/mutation_report.h"
#include "tool/run_context.h"
#include "tool/output_file.h"
#include "tool/scratch_tree.h"
#include "tool/test_time_limits.h"

namespace cc::tool {
namespace {

namespace fs = std::filesystem;

struct MutateArgs {
  std::string catalogue = "tests/mutation/mutants.json";
  std::string source = ".";
  std::string work = "build/mutate";
  int jobs = 1;
  int build_jobs = 1;
  double budget_minutes = 60;
  double campaign_seconds = 60;
  std::uint64_t campaign_seed = 1;
  int campaign_workers = 1;
  double test_timeout = 10;
  std::vector<std::string> labels = {"corpus", "fuzz", "unit", "cli", "hostile", "property"};
  std::vector<std::string> only;
  std::string exclude_tests;
  bool check_only = false;
  bool no_baseline = false;
  std::string report;
  std::string json;
  std::string resume;
  std::string first_catchers;
};

// A scratch copy of the tree with its own build directory.
struct Worker {
  int index = 0;
  fs::path root, tree, build, logs;
  std::vector<std::vector<std::string>> label_targets;  // per label, the ninja targets its tests run
};

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M", &tm);
  return buf;
}

// The commit of the source tree, with "-dirty" when it has uncommitted changes (as the tool's
// own version says it), or "unknown" when it is not a git work tree or git cannot run; with
// "-dirty", a digest of the changes (FNV-1a of `git diff --binary HEAD`: files git does not track
// are not in it), so that two runs on the same dirty commit are told apart. The answers of git go
// to `log`, made anew.
struct SourceState {
  std::string commit, changes;
};

SourceState source_state(const fs::path& source, const fs::path& log) {
  std::error_code ignored;
  fs::remove(log, ignored);  // run_child appends: an older run's commit must not be read
  const ChildResult head = run_child({"git", "-C", source.string(), "rev-parse", "--short=12", "HEAD"}, {}, log, 60);
  std::ifstream in(log);
  std::string commit;
  std::getline(in, commit);
  if (head.exit_status != 0 || commit.empty()) return {"unknown", ""};
  const ChildResult diff = run_child({"git", "-C", source.string(), "diff", "--quiet", "HEAD", "--"}, {}, log, 60);
  if (diff.exit_status == 0) return {commit, ""};
  fs::remove(log, ignored);
  run_child({"git", "-C", source.string(), "diff", "--binary", "HEAD", "--"}, {}, log, 600);
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : read_text(log)) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  char digest[32];
  std::snprintf(digest, sizeof digest, "changes %016llx", static_cast<unsigned long long>(h));
  return {commit + "-dirty", digest};
}

// The program `name` as the shell would find it on PATH, if it is there.
std::optional<fs::path> program_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string_view rest = path ? path : "";
  while (!rest.empty()) {
    const std::size_t colon = rest.find(':');
    const fs::path candidate = fs::path(rest.substr(0, colon)) / name;
    if (!candidate.parent_path().empty() && access(candidate.c_str(), X_OK) == 0) return candidate;
    rest = colon == std::string_view::npos ? std::string_view() : rest.substr(colon + 1);
  }
  return std::nullopt;
}

std::string tail_of(const fs::path& log, std::size_t lines) {
  std::ifstream in(log);
  std::vector<std::string> all;
  for (std::string line; std::getline(in, line);) all.push_back(line);
  std::string out;
  for (std::size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i) out += all[i] + "\n";
  return out;
}

// Runs a setup step; throws naming the log when it fails.
void must(const std::vector<std::string>& argv, const fs::path& cwd, const fs::path& log, const std::string& what) {
  fs::remove(log);
  const ChildResult r = run_child(argv, cwd, log, 0);
  if (r.exit_status != 0) {
    throw std::runtime_error(what + " failed (see " + log.string() + "):\n" + tail_of(log, 15));
  }
}

// Every target ninja can build in the worker's build directory (`ninja -t targets all`), as
// paths relative to it.
std::set<std::string> ninja_targets(const Worker& w) {
  const fs::path out = w.logs / "ninja-targets.txt", err = w.logs / "ninja-targets.err";
  fs::remove(out), fs::remove(err);
  const ChildResult r = run_child({"ninja", "-C", w.build.string(), "-t", "targets", "all"}, {}, out, 600, err);
  if (r.exit_status != 0) throw std::runtime_error("listing ninja's targets failed (see " + err.string() + ")");
  std::set<std::string> targets;
  std::ifstream in(out);
  for (std::string line; std::getline(in, line);) {
    const std::size_t colon = line.rfind(": ");
    if (colon != std::string::npos) targets.insert(line.substr(0, colon));
  }
  return targets;
}

// The ninja targets (paths relative to the build directory) of the executables the tests of a
// label run: every argument word naming a file inside the build directory that ninja builds (a
// file configure wrote, such as a list a test reads, is no target).
std::vector<std::string> targets_of_label(const Worker& w, const std::string& label,
                                          const std::set<std::string>& buildable) {
  const fs::path out = w.logs / ("list-" + label + ".json"), err = w.logs / ("list-" + label + ".err");
  fs::remove(out), fs::remove(err);
  const ChildResult r =
      run_child({"ctest", "--test-dir", w.build.string(), "-N", "-L", "^" + label + "$", "--show-only=json-v1"}, {},
                out, 600, err);
  if (r.exit_status != 0) throw std::runtime_error("listing the tests of label " + label + " failed (see " + err.string() + ")");
  const auto json = nlohmann::json::parse(read_text(out), nullptr, false);
  if (json.is_discarded()) throw std::runtime_error(out.string() + ": ctest's test list does not parse");
  std::set<std::string> targets;
  const std::string prefix = fs::weakly_canonical(w.build).string() + "/";
  const std::regex word(R"([^\s"'()$;=]+)");
  for (const auto& test : json.value("tests", nlohmann::json::array())) {
    for (const auto& arg : test.value("command", nlohmann::json::array())) {
      const std::string text = arg.get<std::string>();
      for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator(); ++it) {
        const std::string path = it->str();
        if (path.rfind(prefix, 0) != 0 || !fs::is_regular_file(path)) continue;
        if (const std::string target = path.substr(prefix.size()); buildable.contains(target)) targets.insert(target);
      }
    }
  }
  return {targets.begin(), targets.end()};
}

// Copies the tree and configures its build; then, once `may_build` returns, builds it with
// `build_jobs` jobs.
void set_up(Worker& w, const MutateArgs& args, int build_jobs, const std::function<void()>& may_build) {
  fs::create_directories(w.logs);
  const SyncCounts c = sync_tree(args.source, w.tree);
  std::printf("worker %d: %s: %d files copied, %d updated, %d removed\n", w.index, w.tree.string().c_str(), c.created,
              c.updated, c.removed);
  std::fflush(stdout);
  if (!fs::exists(w.build / "build.ninja")) {
    // Test discovery at test time: a relinked test binary is not run at build time too.
    std::vector<std::string> configure = {"cmake", "-S", w.tree.string(), "-B", w.build.string(), "-G", "Ninja",
                                          "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_CXX_COMPILER=g++",
                                          "-DCMAKE_GTEST_DISCOVER_TESTS_DISCOVERY_MODE=PRE_TEST"};
    // Reverting a mutant recompiles every file that includes it, as the mutant did: with ccache
    // those compilations are the unmutated tree's, found in the cache (a header's mutant costs
    // one rebuild of its includers instead of two).
    if (const auto ccache = program_on_path("ccache")) configure.push_back("-DCMAKE_CXX_COMPILER_LAUNCHER=" + ccache->string());
    must(configure, {}, w.logs / "configure.log", "configuring " + w.build.string());
  }
  may_build();
  must({"ninja", "-C", w.build.string(), "-j", std::to_string(build_jobs)}, {}, w.logs / "setup-build.log",
       "building the unmutated tree in " + w.build.string());
  const std::set<std::string> buildable = ninja_targets(w);
  for (const std::string& label : args.labels) w.label_targets.push_back(targets_of_label(w, label, buildable));
}

// A ctest -E pattern matching exactly these test names.
std::string exact_names_pattern(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) {
    out += out.empty() ? "^(" : "|";
    for (char c : name) {
      if (std::string_view("\\^$.|?*+()[]{}").find(c) != std::string_view::npos) out += '\\';
      out += c;
    }
  }
  return out.empty() ? out : out + ")$";
}

struct CtestOutcome {
  bool failed = false;
  std::string test;  // the first failing test, and how it failed
  std::vector<std::string> failed_tests;
  std::string problem;  // the run itself went wrong
  double seconds = 0;
};

// Tests with this label check the catalogue against the tree (tests/CMakeLists.txt): a planted
// mutant makes its own entry stale on purpose, so they are left out of every run here.
constexpr const char* kCatalogueLabel = "^catalogue$";

// Runs the tests of a label, leaving out those matching `exclude` (a regex; empty: none) and
// those of kCatalogueLabel; with `only` (a regex), only the tests it matches. With `limits`, ctest is stopped (and the test counts as failed by a
// timeout) when the test it runs passes its limit: ctest runs one test at a time, and its log
// names each test as it starts.
CtestOutcome run_ctest(const Worker& w, const std::string& label, const TestTimeLimits* limits, const fs::path& log,
                       bool stop_on_failure, const std::string& exclude, const std::string& only = {}) {
  fs::remove(log);
  std::vector<std::string> argv = {"ctest", "--test-dir", w.build.string(), "-L",  "^" + label + "$", "--timeout",
                                   "14400", "-LE",        kCatalogueLabel,  "--output-on-failure", "-j1"};
  if (stop_on_failure) argv.push_back("--stop-on-failure");
  if (!exclude.empty()) argv.insert(argv.end(), {"-E", exclude});
  if (!only.empty()) argv.insert(argv.end(), {"-R", only});
  RunningTest running;
  std::optional<std::string> watched;  // the test running now, and since when
  double started = 0;
  std::ifstream follow;
  const auto past_its_limit = [&] {
    if (limits == nullptr) return false;
    if (!follow.is_open()) follow.open(log, std::ios::binary);
    if (!follow.is_open()) return false;
    char chunk[4096];
    while (follow.read(chunk, sizeof chunk) || follow.gcount() > 0) {
      running.feed({chunk, static_cast<std::size_t>(follow.gcount())});
    }
    follow.clear();  // at the end for now: read on from here next time
    if (running.name() != watched) watched = running.name(), started = monotonic_seconds();
    return watched && monotonic_seconds() - started > limits->limit(*watched);
  };
  const ChildResult r = run_child(argv, {}, log, 4 * 3600, {}, past_its_limit);
  CtestOutcome out;
  out.seconds = r.seconds;
  if (interrupted()) {
    out.problem = "interrupted";
  } else if (r.stopped) {
    out.failed = true;
    out.test = *watched + " (Timeout: past " + limits->describe(*watched) + ")";
    out.failed_tests = {*watched};
  } else if (r.exit_status != 0) {
    const auto failed = failed_tests(read_text(log));
    if (failed.empty()) {
      out.problem = "ctest failed without a failing test (see " + log.string() + ")";
    } else {
      out.failed = true;
      out.test = failed.front().first + " (" + failed.front().second + ")";
      for (const auto& f : failed) out.failed_tests.push_back(f.first);
    }
  }
  return out;
}

bool build(const Worker& w, const std::vector<std::string>& targets, const MutateArgs& args, const fs::path& log,
           double& seconds) {
  std::vector<std::string> argv = {"ninja", "-C", w.build.string(), "-j", std::to_string(args.build_jobs)};
  argv.insert(argv.end(), targets.begin(), targets.end());
  const ChildResult r = run_child(argv, {}, log, 3600);
  seconds += r.seconds;
  return r.exit_status == 0;
}

// The first line of a log holding `needle` (with `at_start`, beginning with it).
std::string line_with(const fs::path& log, const std::string& needle, bool at_start = false) {
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);) {
    const std::size_t at = line.find(needle);
    if (at == std::string::npos || (at_start && at != 0)) continue;
    return line.size() > 200 ? line.substr(0, 200) + "..." : line;
  }
  return {};
}

// Applies one mutant in a worker's tree, runs the checks, reverts it. With `first`, the test
// that caught it in an earlier run is run alone before the labels: a catch is a catch whatever
// runs, and it usually catches it again in a few seconds.
void run_mutant(const Worker& w, const MutateArgs& args, const std::string& exclude, const TestTimeLimits& limits,
                const Catcher* first, MutantResult& result) {
  const Mutant& m = result.mutant;
  const fs::path file = w.tree / m.file;
  const double start = monotonic_seconds();
  result.worker = w.index;
  const std::string original = read_text(file);
  if (const auto why = staleness(m, original)) {
    result.status = MutantStatus::stale;
    result.note = *why;
    return;
  }
  write_text(file, mutated(m, original));
  struct Revert {
    const fs::path& file;
    const std::string& text;
    ~Revert() {  // a new modification time: rebuilt at the next build
      try {
        write_text(file, text);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "crosscheck mutate: cannot revert %s: %s\n", file.string().c_str(), e.what());
      }
    }
  } revert{file, original};

  const std::string stem = (w.logs / m.id).string();
  result.status = MutantStatus::survived;
  // Builds what the tests of label i run and runs them (with `only`, those it matches): true
  // when the mutant's checks are over (caught, or they could not go on).
  const auto checked_by = [&](std::size_t i, const std::string& only, const fs::path& log) {
    const fs::path build_log = stem + ".build.log";
    if (!build(w, w.label_targets[i], args, build_log, result.build_seconds)) {
      result.status = interrupted() ? MutantStatus::not_run : MutantStatus::build_failed;
      result.note = "see " + build_log.string();
      return true;
    }
    const CtestOutcome c = run_ctest(w, args.labels[i], &limits, log, true, exclude, only);
    if (!c.problem.empty()) {
      result.status = interrupted() ? MutantStatus::not_run : MutantStatus::error;
      result.note = c.problem;
      return true;
    }
    if (!c.failed) return false;
    result.status = MutantStatus::caught_by_ctest;
    result.check = args.labels[i];
    result.test = c.test;
    result.seconds_to_catch = monotonic_seconds() - start;
    return true;
  };
  const auto first_label = first ? std::find(args.labels.begin(), args.labels.end(), first->label) : args.labels.end();
  bool over = first_label != args.labels.end() &&
              checked_by(static_cast<std::size_t>(first_label - args.labels.begin()), exact_names_pattern({first->test}),
                         stem + ".first.log");
  for (std::size_t i = 0; i < args.labels.size() && !over; ++i) {
    over = checked_by(i, {}, stem + "." + args.labels[i] + ".log");
  }
  if (over) {
    result.seconds = monotonic_seconds() - start;
    return;
  }
  if (args.campaign_seconds > 0) {
    const fs::path build_log = stem + ".build.log";
    if (!build(w, {"crosscheck"}, args, build_log, result.build_seconds)) {
      result.status = MutantStatus::build_failed;
      result.note = "see " + build_log.string();
      result.seconds = monotonic_seconds() - start;
      return;
    }
    const fs::path log = stem + ".campaign.log";
    fs::remove(log);
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", args.campaign_seconds);
    const ChildResult r = run_child({(w.build / "crosscheck").string(), "campaign", "--query", m.query, "--seconds",
                                     seconds, "--seed", std::to_string(args.campaign_seed), "--workers",
                                     std::to_string(args.campaign_workers), "--max-new", "0", "--out",
                                     (w.root / "campaign-new").string(), "--json", stem + ".campaign.json"},
                                    w.tree, log, args.campaign_seconds + 300);
    if (interrupted()) {
      result.status = MutantStatus::not_run;
    } else if (r.timed_out) {
      result.status = MutantStatus::caught_by_campaign;
      result.check = "campaign";
      result.test = "did not finish within its time plus 300 s";
      result.seconds_to_catch = monotonic_seconds() - start;
    } else if (r.exit_status == 1) {
      result.status = MutantStatus::caught_by_campaign;
      result.check = "campaign";
      result.test = line_with(log, "impl_bug ", true);  // the first finding, not a progress line
      result.seconds_to_catch = monotonic_seconds() - start;
    } else if (r.exit_status == 2) {
      result.note = "campaign not run: " + line_with(log, m.query) + " (query kind not in this harness?)";
    } else if (r.exit_status != 0) {
      result.status = MutantStatus::error;
      result.note = "campaign exit status " + std::to_string(r.exit_status) + " (see " + log.string() + ")";
    }
  } else {
    result.note = "no campaign (--campaign-seconds 0)";
  }
  result.seconds = monotonic_seconds() - start;
}

std::string command_line(const MutateArgs& a) {
  std::ostringstream s;
  s << "crosscheck mutate --catalogue " << a.catalogue << " --jobs " << a.jobs << " --budget " << a.budget_minutes
    << " --campaign-seconds " << a.campaign_seconds;
  if (a.campaign_seed != 1) s << " --campaign-seed " << a.campaign_seed;
  for (const std::string& id : a.only) s << " --only " << id;
  if (!a.resume.empty()) s << " --resume " << a.resume;
  if (!a.first_catchers.empty()) s << " --first-catchers " << a.first_catchers;
  return s.str();
}

// The run's settings and one result per mutant of the catalogue (or of --only): stale,
// equivalent and not executable ones decided here, before anything is built; the others are
// returned in `queue`, still not_run.
MutationRun plan_run(const MutateArgs& args, const std::vector<Mutant>& catalogue, std::vector<std::size_t>& queue) {
  MutationRun run;
  run.date = utc_now();
  run.command = command_line(args);
  run.catalogue = args.catalogue;
  run.jobs = args.jobs;
  run.budget_minutes = args.budget_minutes;
  run.campaign_seconds = args.campaign_seconds;
  run.campaign_seed = args.campaign_seed;
  run.labels = args.labels;
  for (const Mutant& m : catalogue) {
    if (!args.only.empty() && std::find(args.only.begin(), args.only.end(), m.id) == args.only.end()) continue;
    MutantResult r;
    r.mutant = m;
    const fs::path file = fs::path(args.source) / m.file;
    const std::optional<std::string> why =
        fs::is_regular_file(file) ? staleness(m, read_text(file)) : std::optional<std::string>("no such file " + file.string());
    if (why) {
      r.status = MutantStatus::stale;
      r.note = *why;
      std::printf("STALE %s: %s\n", m.id.c_str(), why->c_str());
    } else if (!m.equivalent.empty()) {
      r.status = MutantStatus::equivalent;
    } else if (const auto lacking = not_executable_here(m)) {
      r.status = MutantStatus::not_executable;
      r.note = *lacking;
      std::printf("NOT EXECUTABLE HERE %s: %s\n", m.id.c_str(), lacking->c_str());
    } else {
      queue.push_back(run.results.size());
    }
    run.results.push_back(std::move(r));
  }
  return run;
}

int count_of(const MutationRun& run, MutantStatus status) {
  return static_cast<int>(std::count_if(run.results.begin(), run.results.end(),
                                        [&](const MutantResult& r) { return r.status == status; }));
}

// Where the reports go: --report and --json, by default under --work.
std::string report_path(const MutateArgs& args) {
  return args.report.empty() ? (fs::path(args.work) / "report.md").string() : args.report;
}
std::string json_path(const MutateArgs& args) {
  return args.json.empty() ? (fs::path(args.work) / "report.json").string() : args.json;
}

// Both reports, each written whole or not at all (a run killed while writing leaves the last
// one). While the run goes on, the mutants not run yet say so.
void write_reports(const MutateArgs& args, const MutationRun& run) {
  MutationRun shown = run;
  if (!run.finished) {
    for (MutantResult& r : shown.results) {
      if (r.status == MutantStatus::not_run && r.note.empty()) r.note = "not run yet (the run goes on)";
    }
  }
  for (const auto& [path, text] : {std::pair{report_path(args), markdown_report(shown)}, std::pair{json_path(args), json_report(shown)}}) {
    if (const std::string problem = write_output_file(path, text); !problem.empty()) {
      std::fprintf(stderr, "crosscheck mutate: %s\n", problem.c_str());
    }
  }
}

// The workers of a run: each sets up its scratch tree (the first also runs the baseline), then
// takes mutants from the queue until it is empty, the budget would be passed, or the run is
// interrupted. The reports are written again as each mutant ends.
class MutationRunner {
 public:
  MutationRunner(const MutateArgs& args, MutationRun& run, std::vector<std::size_t> queue,
                 std::map<std::string, Catcher> catchers, double start)
      : args_(args), run_(run), queue_(std::move(queue)), catchers_(std::move(catchers)), start_(start),
        exclude_(args.exclude_tests) {
    // With ccache the scratch trees share one cache: paths below the work directory are hashed
    // relative to the build directory, so the first tree's compilations serve the others. The
    // first tree is then built alone with every job, and the others from the cache after it.
    ccache_ = program_on_path("ccache").has_value();
    if (ccache_ && std::getenv("CCACHE_BASEDIR") == nullptr) {
      setenv("CCACHE_BASEDIR", fs::weakly_canonical(args.work).c_str(), 1);
    }
    baseline_done_ = args.no_baseline;
    first_tree_built_ = !ccache_;  // (or failed: the others then fail on their own)
    limits_.floor_seconds = args.test_timeout;
    run_.time_limit_factor = limits_.factor;
    run_.time_limit_floor = limits_.floor_seconds;
  }

  // Runs every worker to its end; false (with the reason in setup_error()) when a tree could
  // not be set up.
  bool run_workers() {
    std::vector<Worker> workers(static_cast<std::size_t>(std::max(1, args_.jobs)));
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < workers.size(); ++i) {
      workers[i].index = static_cast<int>(i);
      // Absolute: the campaign runs inside the tree, and finds its binary and its output there.
      workers[i].root = fs::absolute(args_.work) / ("worker-" + std::to_string(i));
      workers[i].tree = workers[i].root / "tree";
      workers[i].build = workers[i].root / "build";
      workers[i].logs = workers[i].root / "logs";
    }
    jobs_ = static_cast<int>(workers.size());
    for (Worker& w : workers) threads.emplace_back([this, &w] { work(w); });
    for (std::thread& t : threads) t.join();
    return !failed_setup_;
  }

  const std::string& setup_error() const { return setup_error_; }

 private:
  void work(Worker& w) {
    try {
      set_up_tree(w);
      if (w.index == 0 && !args_.no_baseline) run_baseline(w);
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> g(lock_);
      failed_setup_ = true;
      setup_error_ = e.what();
      baseline_done_ = true;
      cv_.notify_all();
      return;
    }
    {
      std::unique_lock<std::mutex> g(lock_);
      cv_.wait(g, [&] { return baseline_done_; });
      run_.setup_seconds = std::max(run_.setup_seconds, monotonic_seconds() - start_);
    }
    while (const std::optional<std::size_t> index = next_mutant()) {
      MutantResult r = run_.results[*index];  // (read under no lock: only this worker writes it)
      try {
        const auto catcher = catchers_.find(r.mutant.id);
        run_mutant(w, args_, exclude_, limits_, catcher == catchers_.end() ? nullptr : &catcher->second, r);
      } catch (const std::exception& e) {
        r.status = MutantStatus::error;
        r.note = e.what();
      }
      finish_mutant(*index, std::move(r));
    }
  }

  // Worker 0 builds first (alone, with every job, when ccache lets the others build from its
  // compilations); the others wait for its build to end, built or not.
  void set_up_tree(Worker& w) {
    const bool first = w.index == 0;
    struct FirstBuilt {
      MutationRunner& runner;
      bool first;
      ~FirstBuilt() {
        if (!first) return;
        std::lock_guard<std::mutex> g(runner.lock_);
        runner.first_tree_built_ = true;
        runner.cv_.notify_all();
      }
    } first_built{*this, first};
    set_up(w, args_, ccache_ && first ? args_.build_jobs * jobs_ : args_.build_jobs, [&] {
      if (first) return;
      std::unique_lock<std::mutex> g(lock_);
      cv_.wait(g, [&] { return first_tree_built_; });
    });
  }

  // ctest on the unmutated tree, label by label: the tests failing there are left out of every
  // mutant's run (say, work in progress), and each test's own time sets its limit.
  void run_baseline(Worker& w) {
    std::vector<std::string> failing;
    std::map<std::string, double> own;
    for (const std::string& label : args_.labels) {
      const fs::path log = w.logs / ("baseline." + label + ".log");
      const CtestOutcome c = run_ctest(w, label, nullptr, log, false, args_.exclude_tests);
      own.merge(passed_test_seconds(read_text(log)));
      if (!c.problem.empty()) throw std::runtime_error("the unmutated tree: label " + label + ": " + c.problem);
      failing.insert(failing.end(), c.failed_tests.begin(), c.failed_tests.end());
      std::lock_guard<std::mutex> g(lock_);
      run_.baseline.emplace_back(label, c.seconds);
      std::printf("baseline: label %s: %zu tests fail on the unmutated tree (see %s), %.0f s\n", label.c_str(),
                  c.failed_tests.size(), log.string().c_str(), c.seconds);
      for (const std::string& t : c.failed_tests) std::printf("  left out of the mutant runs: %s\n", t.c_str());
      std::fflush(stdout);
    }
    std::lock_guard<std::mutex> g(lock_);
    run_.excluded_tests = failing;
    // A test counts as hanging only well past its own time on the unmutated tree: the machine
    // may be shared, and a loaded machine must not make a mutant look caught.
    double slowest = 0;
    for (const auto& [test, seconds] : own) slowest = std::max(slowest, seconds);
    limits_.own_seconds = std::move(own);
    limits_.unknown_seconds = limits_.factor * slowest;
    std::printf("a test times out past %g times its own time on the unmutated tree, at least %g s (%zu tests timed)\n",
                limits_.factor, limits_.floor_seconds, limits_.own_seconds.size());
    if (!failing.empty()) exclude_ += (exclude_.empty() ? "" : "|") + exact_names_pattern(failing);
    baseline_done_ = true;
    cv_.notify_all();
  }

  // The next mutant to run, or none when the queue is done, a worker's setup failed, the run was
  // interrupted, or one more (at the mean cost so far) would pass the budget.
  std::optional<std::size_t> next_mutant() {
    std::lock_guard<std::mutex> g(lock_);
    if (failed_setup_ || interrupted() || next_ == queue_.size()) return std::nullopt;
    const double estimate = done_ ? finished_seconds_ / static_cast<double>(done_) : 120.0;
    if (monotonic_seconds() + estimate > start_ + 60 * args_.budget_minutes) return std::nullopt;
    return queue_[next_++];
  }

  void finish_mutant(std::size_t index, MutantResult r) {
    std::lock_guard<std::mutex> g(lock_);
    ++done_;
    finished_seconds_ += r.seconds;
    const bool caught = r.status == MutantStatus::caught_by_ctest || r.status == MutantStatus::caught_by_campaign;
    std::printf("[%zu/%zu] %-18s %-44s %s%s%s %.0f s\n", done_, queue_.size(), std::string(to_string(r.status)).c_str(),
                r.mutant.id.c_str(), caught ? (r.check + ": " + r.test).c_str() : r.note.c_str(), caught ? "," : "",
                caught ? " after" : "", caught ? r.seconds_to_catch : r.seconds);
    std::fflush(stdout);
    run_.results[index] = std::move(r);
    run_.seconds = monotonic_seconds() - start_;
    run_.finished = false;
    write_reports(args_, run_);
  }

  const MutateArgs& args_;
  MutationRun& run_;
  const std::vector<std::size_t> queue_;
  const std::map<std::string, Catcher> catchers_;  // --first-catchers: by mutant id
  const double start_;
  std::string exclude_;  // ctest -E: --exclude-tests and the tests failing on the unmutated tree
  TestTimeLimits limits_;
  bool ccache_ = false;
  int jobs_ = 1;
  std::mutex lock_;
  std::condition_variable cv_;  // the baseline is done; worker 0's tree is built
  bool baseline_done_ = false, first_tree_built_ = false, failed_setup_ = false;
  std::string setup_error_;
  std::size_t next_ = 0, done_ = 0;
  double finished_seconds_ = 0;
};

// Takes the results of an earlier run's report (--resume) that still hold out of the queue.
// Returns "" or why the report cannot be resumed.
std::string resume(const MutateArgs& args, MutationRun& run, std::vector<std::size_t>& queue) {
  try {
    const MutationRun earlier = read_json_report(args.resume);
    const std::vector<std::size_t> carried = carry_over(run, earlier);
    std::erase_if(queue, [&](std::size_t i) { return std::find(carried.begin(), carried.end(), i) != carried.end(); });
    run.resumed_from = args.resume;
    std::printf("resumed from %s (the run of %s): %zu results carried over, %zu mutants to run\n", args.resume.c_str(),
                earlier.date.c_str(), carried.size(), queue.size());
    return {};
  } catch (const std::runtime_error& e) {
    return e.what();
  }
}

// The end of a run: the reports, the survivors and the score.
int report(const MutateArgs& args, MutationRun& run) {
  for (MutantResult& r : run.results) {
    if (r.status == MutantStatus::not_run && r.note.empty()) {
      r.note = interrupted() ? "interrupted (SIGINT or SIGTERM)" : "the budget would have been exceeded";
    }
  }
  run.finished = true;
  write_reports(args, run);
  for (const MutantResult& r : run.results) {
    if (r.status == MutantStatus::survived) std::printf("SURVIVED %s: %s\n", r.mutant.id.c_str(), r.mutant.description.c_str());
    if (r.status == MutantStatus::not_run) std::printf("not run %s: %s\n", r.mutant.id.c_str(), r.note.c_str());
    if (r.status == MutantStatus::not_executable) {
      std::printf("NOT EXECUTABLE HERE %s: %s\n", r.mutant.id.c_str(), r.note.c_str());
    }
  }
  const Score s = score_of(run);
  const int survived = count_of(run, MutantStatus::survived), stale = count_of(run, MutantStatus::stale),
            errors = count_of(run, MutantStatus::error);
  std::printf("score: ctest alone %d/%d, ctest + campaign %d/%d; %d stale, %d not run, %d errors\n", s.by_ctest,
              s.counted, s.by_either, s.counted, stale, count_of(run, MutantStatus::not_run), errors);
  std::printf("report: %s, %s\n", report_path(args).c_str(), json_path(args).c_str());
  if (interrupted()) return kExitFound;
  return survived || stale || errors ? kExitFound : 0;
}

int run(const MutateArgs& args) {
  const double start = monotonic_seconds();
  std::vector<Mutant> catalogue;
  try {
    catalogue = read_catalogue(args.catalogue);
  } catch (const CatalogueError& e) {
    std::fprintf(stderr, "crosscheck mutate: %s\n", e.what());
    return kExitBadInput;
  }
  for (const std::string& id : args.only) {
    if (std::none_of(catalogue.begin(), catalogue.end(), [&](const Mutant& m) { return m.id == id; })) {
      std::fprintf(stderr, "crosscheck mutate: --only %s: no such mutant in %s\n", id.c_str(), args.catalogue.c_str());
      return kExitBadInput;
    }
  }
  std::vector<std::size_t> queue;
  MutationRun run = plan_run(args, catalogue, queue);
  const int stale = count_of(run, MutantStatus::stale), not_executable = count_of(run, MutantStatus::not_executable);
  std::printf("%zu mutants: %zu to run, %d stale, %d equivalent, %d not executable on this processor\n",
              run.results.size(), queue.size(), stale, count_of(run, MutantStatus::equivalent), not_executable);
  if (args.check_only) return stale ? kExitFound : 0;

  std::map<std::string, Catcher> catchers;
  if (!args.first_catchers.empty()) {
    try {
      catchers = catchers_of(read_json_report(args.first_catchers));
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "crosscheck mutate: --first-catchers %s: %s\n", args.first_catchers.c_str(), e.what());
      return kExitBadInput;
    }
    run.first_catchers_from = args.first_catchers;
    std::printf("first catchers from %s: %zu mutants' earlier catching tests run first\n", args.first_catchers.c_str(),
                catchers.size());
  }

  fs::create_directories(args.work);
  const SourceState source = source_state(args.source, fs::path(args.work) / "commit.log");
  run.commit = source.commit;
  run.changes = source.changes;
  run.processor = processor_description();
  // Named as the workers name their files (absolute), for the Markdown report to show relative.
  run.source_folder = fs::absolute(args.source).lexically_normal().string();
  run.work_folder = fs::absolute(args.work).lexically_normal().string();
  if (!args.resume.empty()) {
    if (const std::string why = resume(args, run, queue); !why.empty()) {
      std::fprintf(stderr, "crosscheck mutate: --resume %s: %s\n", args.resume.c_str(), why.c_str());
      return kExitBadInput;
    }
  }
  // Mutants of one file run one after the other (fewer files to recompile), headers last (a
  // header recompiles much of the tree).
  std::stable_sort(queue.begin(), queue.end(), [&](std::size_t a, std::size_t b) {
    const Mutant &x = run.results[a].mutant, &y = run.results[b].mutant;
    const bool hx = fs::path(x.file).extension() == ".h", hy = fs::path(y.file).extension() == ".h";
    return std::tie(hx, x.file) < std::tie(hy, y.file);
  });

  interrupt_children_on_signal();
  MutationRunner runner(args, run, queue, std::move(catchers), start);
  if (!runner.run_workers()) {
    // An interrupt kills the set-up's build too: say so, not that the build failed.
    std::fprintf(stderr, "crosscheck mutate: %s\n",
                 interrupted() ? "interrupted (SIGINT or SIGTERM) while setting up the scratch trees: no mutant ran"
                               : runner.setup_error().c_str());
    return kExitFound;
  }
  run.seconds = monotonic_seconds() - start;
  return report(args, run);
}

}  // namespace

void add_mutate_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<MutateArgs>();
  auto* cmd = app.add_subcommand("mutate", "Plant each mutant of a catalogue in a scratch copy and see what catches it");
  cmd->add_option("--catalogue", args->catalogue, "The mutant catalogue (JSON)")->capture_default_str();
  cmd->add_option("--source", args->source, "The source tree to copy")->capture_default_str()->check(CLI::ExistingDirectory);
  cmd->add_option("--work", args->work, "Where the scratch copies (worker-N/tree, worker-N/build) and logs go")
      ->capture_default_str()
      ->check(writable_folder());
  cmd->add_option("--jobs", args->jobs, "Mutants run in parallel, each in its own scratch copy")
      ->capture_default_str()
      ->check(whole_in(1, 64));
  cmd->add_option("--build-jobs", args->build_jobs, "ninja -j for each build")->capture_default_str()->check(whole_in(1, 64));
  cmd->add_option("--budget", args->budget_minutes,
                  "Minutes: no mutant is started that would end past it (at the mean cost so far)")
      ->capture_default_str()
      ->check(finite_above(0, 1e6));
  cmd->add_option("--campaign-seconds", args->campaign_seconds, "Campaign on the mutant's query kind (0: none)")
      ->capture_default_str()
      ->check(finite_in(0, 1e6));
  cmd->add_option("--campaign-seed", args->campaign_seed, "Seed of the campaign")->capture_default_str()->check(seed_value());
  cmd->add_option("--campaign-workers", args->campaign_workers, "Worker processes of each campaign")
      ->capture_default_str()
      ->check(whole_in(1, 64));
  cmd->add_option("--test-timeout", args->test_timeout,
                  "Seconds: a test counts as failed (caught) past 5 times its own time on the unmutated tree, and never "
                  "before this (without a baseline: past 600 s)")
      ->capture_default_str()
      ->check(finite_above(0, 1e6));
  cmd->add_option("--labels", args->labels, "ctest labels in the order they run")->capture_default_str()->delimiter(',');
  cmd->add_option("--only", args->only, "Run only this mutant (repeatable)");
  cmd->add_flag("--check", args->check_only, "Only read the catalogue and report stale mutants (exit 1 if any)");
  cmd->add_option("--exclude-tests", args->exclude_tests, "Leave out the tests matching this regex (ctest -E)");
  cmd->add_flag("--no-baseline", args->no_baseline,
                "Skip running ctest on the unmutated tree (whose failing tests are otherwise left out)");
  cmd->add_option("--report", args->report, "Markdown report (default WORK/report.md)")->check(writable_file());
  cmd->add_option("--json", args->json, "JSON report (default WORK/report.json), written again as each mutant ends")
      ->check(writable_file());
  cmd->add_option("--resume", args->resume,
                  "JSON report of an earlier run on the same source (say, one cut short): its results that still "
                  "hold are taken, and only the other mutants run")
      ->check(CLI::ExistingFile);
  cmd->add_option("--first-catchers", args->first_catchers,
                  "JSON report of an earlier run (any source): each mutant it saw caught by a ctest test runs that "
                  "test alone first, then the labels as always")
      ->check(CLI::ExistingFile);
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
