// Second opinions from Chipmunk 7 built in double precision (Debian's libchipmunk-dev), as the
// harness sees them. All of Chipmunk lives in oracle/chipmunk.
#pragma once

#include <string_view>

#include "harness/model/oracle.h"

namespace cc::chipmunk_oracle {

/// The version of Chipmunk this build was compiled against ("7.0.3", from its chipmunk.h).
std::string_view chipmunk_version();
/// The version the loaded library reports (cpVersionString): the same unless the headers and
/// the library differ.
std::string_view chipmunk_library_version();

/// Every kind's Chipmunk parties, each with its name, band and call, are declared in the kind's
/// unit, oracle/chipmunk/kinds/<kind>.cpp (none where Chipmunk has no fair counterpart: the unit
/// says why); `crosscheck bands` lists them. A failed Chipmunk assertion is reported as a failed
/// opinion (chipmunk_call.h); the calls it abandons are counted by oracle/fcl's guard
/// (fcl_oracle::abandoned_calls), so abandoned_calls() here stays 0.
class ChipmunkSecondOpinion final : public harness::SecondOpinion {
 public:
  std::vector<harness::Opinion> opinions(const harness::Input& input) const override;
  std::vector<harness::PartyBand> parties(harness::QueryKind kind) const override;
};

}  // namespace cc::chipmunk_oracle
