#include "oracle/chipmunk/chipmunk_call.h"

#include <chipmunk/chipmunk.h>

#include "harness/model/party.h"
#include "oracle/fcl/time_limit.h"

static_assert(sizeof(cpFloat) == sizeof(double), "Chipmunk must be built with CP_USE_DOUBLES (cpFloat a double)");

namespace cc::chipmunk_oracle {
namespace {

constexpr double kChipmunkTimeLimit = 10;  // seconds of CPU time: the guard is for its assertions

}  // namespace

harness::Opinion chipmunk_call(const std::function<harness::Opinion()>& f) {
  harness::Opinion o;
  const fcl_oracle::Guarded outcome = fcl_oracle::run_guarded(kChipmunkTimeLimit, [&] { o = f(); });
  if (outcome == fcl_oracle::Guarded::timed_out) return harness::timed_out("did not return within 10 s of CPU time");
  if (outcome == fcl_oracle::Guarded::aborted) {
    return harness::failed("aborted: a failed Chipmunk assertion (its message is on stderr)");
  }
  return o;
}

}  // namespace cc::chipmunk_oracle
