#include "harness/processes/interrupts.h"

#include <signal.h>

#include <csignal>
#include <initializer_list>

namespace cc::harness {
namespace {

volatile std::sig_atomic_t g_count = 0;
volatile std::sig_atomic_t g_last = 0;

void on_interrupt(int sig) {
  g_count = g_count + 1;
  g_last = sig;
}

}  // namespace

void count_interrupts() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  action.sa_flags = SA_RESTART;
  sigemptyset(&action.sa_mask);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) sigaction(sig, &action, nullptr);
}

int interrupts() { return g_count; }

int last_interrupt() { return g_last; }

void forget_interrupts() {
  g_count = 0;
  g_last = 0;
}

}  // namespace cc::harness
