// Calling ODE from a party (internal to oracle/ode): ODE initialised once, and its error
// handlers turned into failed opinions.
#pragma once

#include <functional>

#include "harness/model/answer.h"

namespace cc::ode_oracle {

/// Runs f with ODE initialised (dInitODE2 once per process, its data allocated for this thread)
/// and its error, debug and message handlers installed. ODE's dError and dDebug never return (they
/// exit or abort after the handler): the handlers record the message and abort, which the guard of
/// oracle/fcl/time_limit.h turns into a jump out of f; the opinion is then failed with ODE's
/// message (what f allocated is leaked). A dMessage is a warning after which ODE goes on (e.g. its
/// trimesh collider's "contact hash table bucket overflow": close contacts not merged): the
/// answer stands, with the message as its detail. A call that has not returned after 10 s of CPU
/// time is failed.
/// Outside this guard an ODE error prints its message and aborts the process.
harness::Opinion ode_call(const std::function<harness::Opinion()>& f);

}  // namespace cc::ode_oracle
