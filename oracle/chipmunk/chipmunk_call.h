// Calling Chipmunk from a party (internal to oracle/chipmunk): its failed assertions turned into
// failed opinions.
#pragma once

#include <functional>

#include "harness/model/answer.h"

namespace cc::chipmunk_oracle {

/// Runs f under the guard of oracle/fcl/time_limit.h. Chipmunk has no error handler: a failed
/// cpAssertHard (and, in Debian's build, which leaves NDEBUG undefined, a failed cpAssertSoft)
/// prints its message to stderr through cpMessage and calls abort(), which the guard turns into a
/// jump out of f; the opinion is then failed (what f allocated is leaked). A call that has not
/// returned after 10 s of CPU time is failed. Outside this guard a failed assertion aborts the
/// process.
harness::Opinion chipmunk_call(const std::function<harness::Opinion()>& f);

}  // namespace cc::chipmunk_oracle
