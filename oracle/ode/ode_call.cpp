#include "oracle/ode/ode_call.h"

#include <ode/ode.h>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "harness/model/party.h"
#include "oracle/fcl/time_limit.h"

#ifndef dDOUBLE
#error "ODE must be built in double precision (dDOUBLE, Debian's libode-dev)"
#endif
static_assert(sizeof(dReal) == sizeof(double), "ODE must be built in double precision");

namespace cc::ode_oracle {
namespace {

constexpr double kOdeTimeLimit = 10;  // seconds of CPU time: the guard is for ODE's errors

thread_local std::string t_message;   // the first message ODE reported during the call
thread_local bool t_guarded = false;  // inside ode_call

void record(const char* kind, int errnum, const char* msg, va_list ap) {
  char text[512];
  std::vsnprintf(text, sizeof text, msg, ap);
  if (t_message.empty()) t_message = std::string(kind) + " " + std::to_string(errnum) + ": " + text;
}

// dError and dDebug: ODE exits or aborts after these return; abort here, so that the guard
// jumps out of the call (or, unguarded, the process stops with ODE's message).
[[noreturn]] void on_fatal(const char* kind, int errnum, const char* msg, va_list ap) {
  record(kind, errnum, msg, ap);
  if (!t_guarded) std::fprintf(stderr, "crosscheck: %s outside a guarded call\n", t_message.c_str());
  std::abort();
}
void on_error(int errnum, const char* msg, va_list ap) { on_fatal("ODE error", errnum, msg, ap); }
void on_debug(int errnum, const char* msg, va_list ap) { on_fatal("ODE internal error", errnum, msg, ap); }
void on_message(int errnum, const char* msg, va_list ap) { record("ODE message", errnum, msg, ap); }

void ensure_initialised() {
  static const bool initialised = [] {
    dSetErrorHandler(on_error);
    dSetDebugHandler(on_debug);
    dSetMessageHandler(on_message);
    return dInitODE2(0) != 0;
  }();
  thread_local const bool allocated = dAllocateODEDataForThread(dAllocateMaskAll) != 0;
  (void)initialised, (void)allocated;
}

}  // namespace

harness::Opinion ode_call(const std::function<harness::Opinion()>& f) {
  ensure_initialised();
  t_message.clear();
  harness::Opinion o;
  t_guarded = true;
  const fcl_oracle::Guarded outcome = fcl_oracle::run_guarded(kOdeTimeLimit, [&] { o = f(); });
  t_guarded = false;
  if (outcome == fcl_oracle::Guarded::timed_out) return harness::timed_out("did not return within 10 s of CPU time");
  if (outcome == fcl_oracle::Guarded::aborted) {
    return harness::failed(t_message.empty() ? std::string("aborted") : t_message);
  }
  if (!t_message.empty() && o.detail.empty()) o.detail = t_message;  // a warning: the answer stands
  return o;
}

}  // namespace cc::ode_oracle
