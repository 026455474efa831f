#include "oracle/fcl/time_limit.h"

#include <setjmp.h>
#include <signal.h>
#include <sys/time.h>

namespace cc::fcl_oracle {
namespace {

sigjmp_buf g_escape;
volatile sig_atomic_t g_armed = 0;
int g_abandoned = 0;

void on_alarm(int) {
  if (g_armed) siglongjmp(g_escape, 1);
}

void on_abort(int) {
  if (g_armed) siglongjmp(g_escape, 2);
}

void set_timer(double seconds) {
  itimerval t{};
  t.it_value.tv_sec = static_cast<time_t>(seconds);
  t.it_value.tv_usec = static_cast<suseconds_t>((seconds - static_cast<double>(t.it_value.tv_sec)) * 1e6);
  setitimer(ITIMER_VIRTUAL, &t, nullptr);
}

}  // namespace

Guarded run_guarded(double seconds, const std::function<void()>& f) {
  struct sigaction alarm_action {}, abort_action {};
  struct sigaction previous_alarm {}, previous_abort {};
  alarm_action.sa_handler = on_alarm;
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
