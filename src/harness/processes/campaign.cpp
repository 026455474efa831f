#include "harness/processes/campaign.h"

#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <sstream>
#include <system_error>

#include "harness/formats/case_file.h"
#include "harness/generation/generate.h"
#include "harness/model/party.h"
#include "harness/model/library.h"
#include "harness/model/subject.h"
#include "harness/formats/write_all.h"
#include "harness/processes/child.h"
#include "harness/processes/evaluate_in_child.h"
#include "harness/processes/interrupts.h"
#include "harness/processes/subject_process.h"

namespace cc::harness {
namespace {

using Clock = std::chrono::steady_clock;

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
}

// What a worker is doing, in memory shared with the supervisor: enough to rebuild the case it
// is on if it dies, and to tell which party it was in.
// A worker is `starting` until its oracles are made, then `idle` between cases.
enum Phase : int { idle = 0, in_library = 1, in_exact = 2, in_second_opinion = 3, starting = 4 };

constexpr std::size_t kKinds = std::size(kAllQueryKinds);
constexpr std::size_t kClasses = std::size(kAllClasses);

struct Slot {
  std::atomic<int> phase{idle};
  std::atomic<int> kind{0};
  std::atomic<std::uint64_t> case_index{0};
  std::atomic<std::int64_t> started_ns{0};
  std::atomic<bool> hung{false};                // set by the supervisor before it kills a worker that hangs
  std::atomic<std::uint64_t> next[kKinds];      // next case number per kind
  // The worker's tallies live here too, so that none is lost when it dies.
  std::atomic<std::uint64_t> counts[kKinds][kClasses];
  std::atomic<std::int64_t> busy_ns[kKinds];
  std::atomic<std::uint64_t> findings_sent{0};  // "F" lines the worker (and those before it) wrote
  // A fatal signal another process sent the worker (its handler notes it), not one it raised.
  std::atomic<int> outside_signal{0};
  // The case to ask again, first, when a worker was killed from outside in it; kept after it
  // is asked, so that a second such death in the same case is that case's finding.
  std::atomic<bool> ask_again{false};
  std::atomic<int> again_kind{-1};
  std::atomic<std::uint64_t> again_index{0};
};

// The slot of this worker, for its signal handler.
Slot* g_worker_slot = nullptr;

// A fatal signal in a worker: noted in its slot when another process sent it (kill, not a
// fault, a timer, the terminal nor the worker's own abort), then taken as it would have been:
// the handler is reset on entry, and the signal raised again is pending until it returns.
void note_fatal_signal(int signal, siginfo_t* info, void*) {
  const bool sent = info->si_code == SI_USER || info->si_code == SI_QUEUE || info->si_code == SI_TKILL;
  if (sent && info->si_pid != ::getpid() && g_worker_slot != nullptr) g_worker_slot->outside_signal = signal;
  ::raise(signal);
}

void note_fatal_signals(Slot& slot) {
  g_worker_slot = &slot;
  slot.outside_signal = 0;
  struct sigaction action {};
  action.sa_sigaction = note_fatal_signal;
  action.sa_flags = SA_SIGINFO | SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  for (const int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS, SIGUSR1, SIGUSR2, SIGALRM, SIGQUIT}) {
    sigaction(s, &action, nullptr);
  }
}

// The party a worker died in (a phase in a case: in_library, in_exact or in_second_opinion).
DiedIn died_in(int phase) {
  return phase == in_library ? DiedIn::library : (phase == in_exact ? DiedIn::exact : DiedIn::second_opinions);
}

// A worker that dies outside every party (starting, or between cases: drawing, judging or
// passing a case on) died of the harness's own fault, which no case can hold: a problem of the
// run. After this many, its slot is not given another worker.
constexpr int kHarnessDeathsPerSlot = 3;

void write_line(int fd, const std::string& line) { write_all(fd, line + "\n"); }

std::string format_seconds(double s) {
  std::ostringstream out;
  out << s << " s";
  return out.str();
}

// Out of contract, a case is a finding when a second opinion's answer differs from the exact
// one (or, with no exact verdict, from the library's documented one): FCL's users want to know.
bool is_finding(const Verdict& v) {
  const CaseClass c = v.cls;
  if (c == CaseClass::out_of_contract) {
    return std::any_of(v.parties.begin() + 1, v.parties.end(), [](const PartyStanding& p) {
      return p.standing == Standing::wrong || p.standing == Standing::failed || p.standing == Standing::differs;
    });
  }
  return c == CaseClass::impl_bug || c == CaseClass::oracle_defect || c == CaseClass::oracle_crash ||
         c == CaseClass::undecided;
}

// What the case made anyone print: the worker's own output files (a peer's messages), then the
// subject's (each call that printed is also the subject's failure).
std::optional<std::string> printed_in_case(bool captured_output) {
  std::optional<std::string> said;
  if (captured_output) {
    std::fflush(stdout);
    if (auto err = take_captured_line(STDERR_FILENO)) said = std::move(err);
    if (auto out = take_captured_line(STDOUT_FILENO); out && !said) said = "standard output: " + *out;
  }
  if (auto subject = take_subject_output(); subject && !said) said = "the subject's " + *subject;
  return said;
}

// A worker's exit status when it stops early because its second opinion abandoned a call (see
// SecondOpinion::abandoned_calls): it is replaced, and nothing is recorded against its last case.
constexpr int kRetired = 3;

// The worker: runs cases until the deadline, reporting tallies and findings on `out`.
[[noreturn]] void run_worker(int worker, const CampaignOptions& options, const Oracles& oracles, Slot& slot, int out,
                             std::int64_t deadline_ns) {
  // Its standard output and error go to files: what FCL or Eigen print there is counted per
  // case, and its first line reported, instead of reaching the terminal raw.
  std::fflush(stdout);
  const bool captured_output = capture_to_file(STDERR_FILENO) && capture_to_file(STDOUT_FILENO);
  note_fatal_signals(slot);
  const auto exact = oracles.exact();
  const auto second = oracles.second();
  slot.phase = idle;
  const int abandoned_before = second->abandoned_calls();  // inherited: a fresh worker cannot undo it
  while (interrupts() == 0 && now_ns() < deadline_ns) {
    // Equal time for every kind: the one this worker has spent least time on goes next.
    QueryKind kind = options.kinds.front();
    for (QueryKind k : options.kinds) {
      if (slot.busy_ns[static_cast<std::size_t>(k)] < slot.busy_ns[static_cast<std::size_t>(kind)]) kind = k;
    }
    std::uint64_t index = 0;
    if (slot.ask_again.exchange(false)) {  // the case its predecessor was killed in from outside
      kind = static_cast<QueryKind>(slot.again_kind.load());
      index = slot.again_index;
    } else {
      const std::uint64_t n = slot.next[static_cast<std::size_t>(kind)].fetch_add(1);
      index = static_cast<std::uint64_t>(worker) + static_cast<std::uint64_t>(options.workers) * n;
    }
    const auto kind_number = static_cast<std::size_t>(kind);
    const std::int64_t start = now_ns();
    slot.kind = static_cast<int>(kind);
    slot.case_index = index;
    slot.started_ns = start;
    const Input input = campaign_case(options.seed, kind, index, options.out_of_contract_percent, options.mesh_folder);

    Evaluation e;
    slot.phase = in_library;
    ask_library_into(e, input);  // a subject's failure is its answer's, not the worker's end
    e.opinions = library_alternatives(input);
    slot.phase = in_exact;
    e.exact = exact->judge(input);
    slot.phase = in_second_opinion;
    for (Opinion& o : second->opinions(input)) e.opinions.push_back(std::move(o));
    slot.phase = idle;
    judge_into(e, input);

    const std::int64_t elapsed = now_ns() - start;
    slot.busy_ns[kind_number] += elapsed;
    slot.counts[kind_number][static_cast<std::size_t>(e.verdict.cls)] += 1;
    if (const auto said = printed_in_case(captured_output)) {
      write_line(out, "E " + std::to_string(static_cast<int>(kind)) + " " + std::to_string(index) + " " + *said);
    }
    if (is_finding(e.verdict)) {  // with the answers, as case files store them (exactly)
      write_line(out, "F " + std::to_string(static_cast<int>(kind)) + " " + std::to_string(index) + " " +
                          answers_to_json(e).dump(-1, ' ', false, Json::error_handler_t::replace));
      slot.findings_sent += 1;  // once the write returned, whether it failed or not
    }
    if (second->abandoned_calls() > abandoned_before) {  // later cases must not pay for it
      ::close(out);
      std::_Exit(kRetired);
    }
  }
  ::close(out);
  std::_Exit(0);
}

struct Worker {
  pid_t pid = -1;
  int fd = -1;
  std::string buffer;
  bool stopped = false;  // killed by the supervisor because the run stops: not a finding
};

// After an interrupt or at the deadline, a worker gets SIGTERM (it ends after its case) and,
// this long after, SIGKILL: every worker stops within a second.
constexpr std::int64_t kStopGraceNs = 500'000'000;

// The supervisor of a campaign: starts the workers, reads their findings, replaces those that
// end early, tells a death in a case (a finding) from one outside every case (a problem of the
// run) or from outside the run (the case asked again), and kills a case that hangs.
class Supervisor {
 public:
  Supervisor(const CampaignOptions& options, const Oracles& oracles, Slot* slots)
      : options_(options),
        oracles_(oracles),
        slots_(slots),
        workers_(static_cast<std::size_t>(options.workers)),
        harness_deaths_(workers_.size(), 0),
        start_ns_(now_ns()),
        deadline_ns_(start_ns_ + static_cast<std::int64_t>(options.seconds * 1e9)) {
    result_.seed = options.seed;
  }

  CampaignResult run() {
    std::size_t alive = 0;
    for (int w = 0; w < options_.workers; ++w) alive += spawn(w) ? 1 : 0;
    result_.workers = static_cast<int>(alive);  // the rates are those of the workers that ran
    // The supervisor's own references, made after the workers forked (they make theirs).
    exact_ = oracles_.exact();
    second_ = oracles_.second();
    while (alive > 0) {
      stop_workers_when_due();
      std::vector<pollfd> fds;
      for (const Worker& w : workers_) fds.push_back({w.fd, POLLIN, 0});
      poll(fds.data(), fds.size(), 100);
      for (std::size_t i = 0; i < workers_.size(); ++i) {
        if (workers_[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP))) continue;
        if (read_from(workers_[i])) continue;
        if (!reap(i)) --alive;
      }
      kill_hung_cases();
      report_progress();
    }
    result_.seconds = static_cast<double>(now_ns() - start_ns_) * 1e-9;
    result_.tallies = tallies();
    result_.interrupted = interrupts() > 0;
    // Never lose a finding silently: one a worker sent that did not arrive is a problem of the run.
    std::uint64_t findings_sent = 0;
    for (int w = 0; w < options_.workers; ++w) findings_sent += slots_[w].findings_sent;
    if (findings_sent > findings_received_) {
      result_.problems.push_back(std::to_string(findings_sent - findings_received_) +
                                 " findings of the workers never reached the campaign (a worker's report was cut off)");
    }
    return std::move(result_);
  }

 private:
  bool stopping() const { return interrupts() > 0 || now_ns() >= deadline_ns_; }

  // Starts worker w; false (and a problem recorded) when the pipe or the fork fails.
  bool spawn(int w) {
    slots_[w].phase = starting;
    try {
      const Child child = start_child([&](int out) -> int { run_worker(w, options_, oracles_, slots_[w], out, deadline_ns_); });
      workers_[static_cast<std::size_t>(w)] = {child.pid, child.out, "", false};
      return true;
    } catch (const std::system_error& e) {
      workers_[static_cast<std::size_t>(w)] = {};
      result_.problems.push_back("worker " + std::to_string(w) + " could not be started (" + e.what() +
                                 "); the campaign went on without it");
      return false;
    }
  }

  // At the deadline or an interrupt every worker gets SIGTERM, and SIGKILL after the grace.
  void stop_workers_when_due() {
    if (stop_ns_ == 0 && stopping()) {
      stop_ns_ = now_ns();
      for (const Worker& w : workers_) {
        if (w.fd >= 0) kill(w.pid, SIGTERM);
      }
    }
    if (stop_ns_ != 0 && now_ns() - stop_ns_ > kStopGraceNs) {
      for (Worker& w : workers_) {
        if (w.fd >= 0 && !w.stopped) {
          w.stopped = true;
          kill(w.pid, SIGKILL);
        }
      }
    }
  }

  // Reads what a worker wrote and handles each whole line; false at the end of its pipe.
  bool read_from(Worker& w) {
    char chunk[4096];
    const ssize_t n = ::read(w.fd, chunk, sizeof chunk);
    if (n <= 0) return false;
    w.buffer.append(chunk, static_cast<std::size_t>(n));
    std::size_t eol;
    while ((eol = w.buffer.find('\n')) != std::string::npos) {
      handle_line(w.buffer.substr(0, eol));
      w.buffer.erase(0, eol + 1);
    }
    return true;
  }

  // A worker's line: "F <kind> <case index> <answers>" (a finding) or "E <kind> <case index>
  // <first line>" (a case that wrote to standard error).
  void handle_line(const std::string& line) {
    std::istringstream in(line);
    char tag = 0;
    int kind_number = 0;
    std::uint64_t index = 0;
    in >> tag >> kind_number >> index;
    if (!in) return;
    const auto kind = static_cast<QueryKind>(kind_number);
    std::string rest;
    std::getline(in, rest);
    if (tag == 'E') {
      if (result_.noisy_cases++ == 0) result_.first_noise = std::string(name(kind)) + " case " + std::to_string(index) + ":" + rest;
      return;
    }
    if (tag != 'F') return;
    std::optional<Json> answers;
    try {
      answers = Json::parse(rest);
    } catch (const std::exception&) {
    }
    ++findings_received_;
    record_finding(kind, index, "", idle, answers);
  }

  void record_finding(QueryKind kind, std::uint64_t index, const std::string& crash, int phase,
                      const std::optional<Json>& answers) {
    Finding f;
    f.kind = kind;
    f.case_index = index;
    f.input = campaign_case(options_.seed, kind, index, options_.out_of_contract_percent, options_.mesh_folder);
    f.crash = crash;
    bool answered = false;
    if (crash.empty() && answers) {  // it returned in the worker, which sent the answers it got
      try {
        answers_from_json(*answers, *second_, kind, f.evaluation);
        f.evaluation.exact = exact_->judge(f.input);
        judge_into(f.evaluation, f.input);
        answered = true;
      } catch (const std::exception&) {
        f.evaluation = {};
      }
    }
    if (crash.empty() && !answered) {  // (answers that did not parse) the same again, first in a child
      if (auto e = evaluate_in_child(f.input, *exact_, *second_)) {
        f.evaluation = std::move(*e);
      } else {
        const std::string how = "died when asked again in a child process";
        f.evaluation = evaluation_after_death(f.input, *exact_, *second_, DiedIn::second_opinions, how);
        f.crash = death_text(how, DiedIn::second_opinions);
        f.died_in = DiedIn::second_opinions;
      }
    }
    if (!crash.empty()) {  // rebuilt without the party that died, as every command rebuilds it
      f.evaluation = evaluation_after_death(f.input, *exact_, *second_, died_in(phase), crash);
      f.crash = death_text(crash, died_in(phase));
      f.died_in = died_in(phase);
      KindTally& t = crashed_[kind];
      t.cases += 1;
      t.by_class[static_cast<std::size_t>(f.evaluation.verdict.cls)] += 1;
    }
    result_.findings.push_back(std::move(f));
  }

  // A worker whose pipe ended: reaped, and its end judged. True when it was replaced (or its
  // slot goes on), false when the slot is done.
  bool reap(std::size_t i) {
    Worker& w = workers_[i];
    ::close(w.fd);
    w.fd = -1;
    const ChildEnd end = wait_child(w.pid);
    Slot& slot = slots_[i];
    const bool retired = end.status == kRetired && slot.phase == idle;
    const bool in_a_case = slot.phase != idle && slot.phase != starting;
    // Ended by the SIGTERM or SIGKILL that stopped the run: its last case is not a finding.
    const bool stopped = w.stopped || (stop_ns_ != 0 && !slot.hung && end.signal == SIGTERM);
    // Killed from outside (a SIGKILL the supervisor did not send, a signal another process
    // sent): an interruption, not the case's fault. The case is asked again, once: a second
    // such death in it is its finding (an out-of-memory kill, say).
    const bool from_outside = !stopped && !retired && end.signal != 0 && !slot.hung &&
                              (end.signal == SIGKILL || slot.outside_signal == end.signal);
    const bool asked_before = slot.again_kind == slot.kind && slot.again_index == slot.case_index;
    const bool interrupted = from_outside && (!in_a_case || !asked_before);
    if (interrupted && in_a_case && !stopping()) {  // a run that stops asks nothing again
      slot.again_kind = slot.kind.load();
      slot.again_index = slot.case_index.load();
      slot.ask_again = true;
      slot.phase = idle;
      ++result_.asked_again;
    }
    // An exit in the middle of a case, whatever its status (0 too), is a death in that case.
    const bool died = (!end.succeeded() || in_a_case) && !retired && !stopped && !interrupted;
    // A worker that ended early without dying (retired, interrupted) is replaced.
    if (!died && !stopped && !stopping()) return spawn(static_cast<int>(i));
    if (died && !in_a_case) {
      const bool was_starting = slot.phase == starting;
      result_.problems.push_back("worker " + std::to_string(i) + " " + end.what() +
                                 (was_starting ? " while starting"
                                               : " between cases, after " + std::string(name(static_cast<QueryKind>(slot.kind.load()))) +
                                                     " case " + std::to_string(slot.case_index.load())) +
                                 " (the harness's own failure: no party was asking)");
      slot.phase = idle;
      return ++harness_deaths_[i] < kHarnessDeathsPerSlot && !stopping() && spawn(static_cast<int>(i));
    }
    if (died) {
      std::string what = end.what();
      if (from_outside) what += ", sent by another process, in the case asked again after the same";
      if (slot.hung) what = std::string(kTimedOut) + ": hung for more than " + format_seconds(options_.case_timeout_seconds);
      record_finding(static_cast<QueryKind>(slot.kind.load()), slot.case_index, what, slot.phase, std::nullopt);
      slot.phase = idle;
      slot.hung = false;
      return !stopping() && spawn(static_cast<int>(i));  // its counters skip the case it died on
    }
    return false;
  }

  // Hangs: a case that has run too long is killed; the worker is then reaped. A subject's call
  // has a time limit of its own (subject_process.h): its hang is its answer's.
  void kill_hung_cases() {
    for (std::size_t i = 0; i < workers_.size(); ++i) {
      Slot& slot = slots_[i];
      const int phase = slot.phase;
      if (phase == in_library && subject_under_test() != nullptr) continue;
      if (options_.case_timeout_seconds > 0 && workers_[i].fd >= 0 && !workers_[i].stopped && phase != idle &&
          phase != starting && !slot.hung &&
          now_ns() - slot.started_ns > static_cast<std::int64_t>(options_.case_timeout_seconds * 1e9)) {
        slot.hung = true;
        kill(workers_[i].pid, SIGKILL);
      }
    }
  }

  void report_progress() {
    const std::int64_t now = now_ns();
    if (!options_.progress || now - last_progress_ns_ < 1'000'000'000) return;
    last_progress_ns_ = now;
    std::uint64_t cases = 0, bugs = 0;
    for (const auto& [kind, t] : tallies()) cases += t.cases, bugs += t.count(CaseClass::impl_bug);
    std::ostringstream line;
    line << "[" << static_cast<int>(static_cast<double>(now - start_ns_) * 1e-9) << "/"
         << static_cast<int>(options_.seconds) << " s] " << cases << " cases, " << bugs << " impl_bug, "
         << result_.findings.size() << " findings";
    options_.progress(line.str());
  }

  // The tallies: the workers' shared counters plus the cases they died on.
  std::map<QueryKind, KindTally> tallies() const {
    std::map<QueryKind, KindTally> all = crashed_;
    for (QueryKind kind : options_.kinds) {
      const auto k = static_cast<std::size_t>(kind);
      KindTally& t = all[kind];
      for (int w = 0; w < options_.workers; ++w) {
        for (std::size_t c = 0; c < kClasses; ++c) {
          const std::uint64_t n = slots_[w].counts[k][c];
          t.by_class[c] += n;
          t.cases += n;
        }
        t.busy_seconds += static_cast<double>(slots_[w].busy_ns[k].load()) * 1e-9;
      }
    }
    return all;
  }

  const CampaignOptions& options_;
  const Oracles& oracles_;
  Slot* slots_;
  std::unique_ptr<ExactReference> exact_;  // to judge what the workers send
  std::unique_ptr<SecondOpinion> second_;
  CampaignResult result_;
  std::vector<Worker> workers_;
  std::map<QueryKind, KindTally> crashed_;  // cases on which a worker died
  std::vector<int> harness_deaths_;          // per slot: deaths outside every party
  std::uint64_t findings_received_ = 0;
  const std::int64_t start_ns_, deadline_ns_;
  std::int64_t stop_ns_ = 0;  // when the workers were told to stop
  std::int64_t last_progress_ns_ = 0;
};

}  // namespace

Input campaign_case(std::uint64_t seed, QueryKind kind, std::uint64_t case_index, int out_of_contract_percent,
                    const std::filesystem::path& mesh_folder) {
  RandomChoices choices(mix_seed(mix_seed(seed, static_cast<std::uint64_t>(kind)), case_index));
  GenerateOptions options;
  options.mesh_folder = mesh_folder;
  options.out_of_contract = choices.chance(out_of_contract_percent);
  return generate(kind, choices, options);
}

double cases_per_second(const KindTally& tally, int workers) {
  if (tally.busy_seconds <= 0) return 0;
  return static_cast<double>(tally.cases) / (tally.busy_seconds / workers);
}

CampaignResult run_campaign(const CampaignOptions& options, const Oracles& oracles) {
  auto* slots = static_cast<Slot*>(mmap(nullptr, sizeof(Slot) * static_cast<std::size_t>(options.workers),
                                        PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0));
  if (slots == MAP_FAILED) throw std::runtime_error("campaign: cannot map shared memory");
  for (int w = 0; w < options.workers; ++w) new (&slots[w]) Slot();
  count_interrupts();
  CampaignResult result = Supervisor(options, oracles, slots).run();
  munmap(slots, sizeof(Slot) * static_cast<std::size_t>(options.workers));
  return result;
}

}  // namespace cc::harness
