#include "oracle/fcl/time_limit.h"

#include <link.h>
#include <setjmp.h>
#include <signal.h>
#include <sys/time.h>
#include <ucontext.h>

#include <cstdint>
#include <string_view>

namespace cc::fcl_oracle {
namespace {

sigjmp_buf g_escape;
volatile sig_atomic_t g_armed = 0;
int g_abandoned = 0;

// The code of the C and C++ runtimes (the C library with its allocator, the dynamic loader, the
// unwinder, the C++ library, a sanitizer's allocator): a call interrupted there may be inside
// malloc or hold a lock, and a jump out would leave the heap or the lock broken for the rest of
// the process. Found once, before the first timer is armed. (A sanitizer linked statically, as
// clang links libFuzzer's, is in the executable and not told apart.)
struct CodeRange {
  std::uintptr_t begin = 0, end = 0;
};
CodeRange g_runtime[16];
int g_runtime_count = -1;

int note_runtime(dl_phdr_info* info, std::size_t, void*) {
  const std::string_view path = info->dlpi_name != nullptr ? info->dlpi_name : "";
  const std::string_view file = path.substr(path.rfind('/') + 1);  // npos + 1: all of it
  bool runtime = false;
  for (const std::string_view prefix : {"libc.so", "ld-linux", "libgcc_s.so", "libstdc++.so", "libasan.so", "libubsan.so"}) {
    runtime = runtime || file.starts_with(prefix);
  }
  for (int i = 0; runtime && i < info->dlpi_phnum && g_runtime_count < 16; ++i) {
    const ElfW(Phdr)& segment = info->dlpi_phdr[i];
    if (segment.p_type != PT_LOAD || (segment.p_flags & PF_X) == 0) continue;
    const std::uintptr_t begin = info->dlpi_addr + segment.p_vaddr;
    g_runtime[g_runtime_count++] = {begin, begin + segment.p_memsz};
  }
  return 0;
}

bool in_runtime(std::uintptr_t pc) {
  for (int i = 0; i < g_runtime_count; ++i) {
    if (pc >= g_runtime[i].begin && pc < g_runtime[i].end) return true;
  }
  return false;
}

// Where the interrupted code was; 0 where the context does not say.
std::uintptr_t interrupted_pc(const void* context) {
  const auto* uc = static_cast<const ucontext_t*>(context);
#if defined(__x86_64__)
  return static_cast<std::uintptr_t>(uc->uc_mcontext.gregs[REG_RIP]);
#elif defined(__aarch64__)
  return static_cast<std::uintptr_t>(uc->uc_mcontext.pc);
#else
  (void)uc;
  return 0;
#endif
}

void set_timer(double seconds) {
  itimerval t{};
  t.it_value.tv_sec = static_cast<time_t>(seconds);
  t.it_value.tv_usec = static_cast<suseconds_t>((seconds - static_cast<double>(t.it_value.tv_sec)) * 1e6);
  setitimer(ITIMER_VIRTUAL, &t, nullptr);
}

// Out of the call, unless it was interrupted inside the runtimes: then again a millisecond of CPU
// time later, until it is in its own code (libccd's loops spend most of their time there).
void on_alarm(int, siginfo_t*, void* context) {
  if (!g_armed) return;
  if (in_runtime(interrupted_pc(context))) {
    set_timer(0.001);
    return;
  }
  siglongjmp(g_escape, 1);
}

void on_abort(int) {
  if (g_armed) siglongjmp(g_escape, 2);
}

}  // namespace

Guarded run_guarded(double seconds, const std::function<void()>& f) {
  struct sigaction alarm_action {}, abort_action {};
  struct sigaction previous_alarm {}, previous_abort {};
  if (g_runtime_count < 0) {
    g_runtime_count = 0;
    dl_iterate_phdr(note_runtime, nullptr);
  }
  alarm_action.sa_sigaction = on_alarm;
  alarm_action.sa_flags = SA_SIGINFO;
  abort_action.sa_handler = on_abort;
  sigemptyset(&alarm_action.sa_mask);
  sigemptyset(&abort_action.sa_mask);
  sigaction(SIGVTALRM, &alarm_action, &previous_alarm);
  sigaction(SIGABRT, &abort_action, &previous_abort);
  Guarded outcome = Guarded::returned;
  if (const int jumped = sigsetjmp(g_escape, 1); jumped == 0) {
    g_armed = 1;
    set_timer(seconds);
    f();
  } else {
    outcome = jumped == 1 ? Guarded::timed_out : Guarded::aborted;
    ++g_abandoned;
  }
  g_armed = 0;
  set_timer(0);
  sigaction(SIGABRT, &previous_abort, nullptr);
  sigaction(SIGVTALRM, &previous_alarm, nullptr);
  return outcome;
}

int abandoned_calls() { return g_abandoned; }

bool run_with_time_limit(double seconds, const std::function<void()>& f) {
  return run_guarded(seconds, f) == Guarded::returned;
}

}  // namespace cc::fcl_oracle
