#include "oracle/fcl/time_limit.h"

#include <setjmp.h>
#include <signal.h>
#include <sys/time.h>

namespace cc::fcl_oracle {
namespace {

sigjmp_buf g_escape;
volatile sig_atomic_t g_armed = 0;

void on_alarm(int) {
  if (g_armed) siglongjmp(g_escape, 1);
}

void set_timer(double seconds) {
  itimerval t{};
  t.it_value.tv_sec = static_cast<time_t>(seconds);
  t.it_value.tv_usec = static_cast<suseconds_t>((seconds - static_cast<double>(t.it_value.tv_sec)) * 1e6);
  setitimer(ITIMER_VIRTUAL, &t, nullptr);
}

}  // namespace

bool run_with_time_limit(double seconds, const std::function<void()>& f) {
  struct sigaction action {};
  struct sigaction previous {};
  action.sa_handler = on_alarm;
  sigemptyset(&action.sa_mask);
  sigaction(SIGVTALRM, &action, &previous);
  bool finished = false;
  if (sigsetjmp(g_escape, 1) == 0) {
    g_armed = 1;
    set_timer(seconds);
    f();
    finished = true;
  }
  g_armed = 0;
  set_timer(0);
  sigaction(SIGVTALRM, &previous, nullptr);
  return finished;
}

}  // namespace cc::fcl_oracle
