// Second opinions from FCL 0.7 and libccd, as the harness sees them. All of FCL lives here.
#pragma once

#include <string_view>

#include "harness/model/oracle.h"

namespace cc::fcl_oracle {

/// The version of FCL this build was compiled against, as its headers give it ("0.7.0").
std::string_view fcl_version();

/// Every kind's parties, each with its name, band and call, are declared in the kind's unit,
/// oracle/fcl/kinds/<kind>.cpp; `crosscheck bands` lists them. A C++ exception thrown by FCL or
/// libccd is caught and reported as a failed opinion.
class FclSecondOpinion final : public harness::SecondOpinion {
 public:
  FclSecondOpinion();  // checks that FCL's collision matrix has the pairs used
  std::vector<harness::Opinion> opinions(const harness::Input& input) const override;
  std::vector<harness::PartyBand> parties(harness::QueryKind kind) const override;
  /// The libccd, manager and continuous-collision calls abandoned by their time limit or
  /// abort guard so far (time_limit.h).
  int abandoned_calls() const override;
};

}  // namespace cc::fcl_oracle
