// Second opinions from ODE 0.16 built in double precision (Debian's libode-dev), as the harness
// sees them. All of ODE lives in oracle/ode.
#pragma once

#include <string_view>

#include "harness/model/oracle.h"

namespace cc::ode_oracle {

/// The version of ODE this build was compiled against ("0.16.2", from pkg-config).
std::string_view ode_version();

/// Every kind's ODE parties, each with its name, band and call, are declared in the kind's
/// unit, oracle/ode/kinds/<kind>.cpp (none where ODE has no fair counterpart: the unit says
/// why); `crosscheck bands` lists them. An ODE error is reported as a failed opinion (ode_call.h);
/// the calls it abandons are counted by oracle/fcl's guard (fcl_oracle::abandoned_calls), so
/// abandoned_calls() here stays 0.
class OdeSecondOpinion final : public harness::SecondOpinion {
 public:
  std::vector<harness::Opinion> opinions(const harness::Input& input) const override;
  std::vector<harness::PartyBand> parties(harness::QueryKind kind) const override;
};

}  // namespace cc::ode_oracle
