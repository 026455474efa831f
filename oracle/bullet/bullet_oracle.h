// Second opinions from Bullet 3.24 built in double precision (Debian's bullet-float64), as the
// harness sees them. All of Bullet lives in oracle/bullet.
#pragma once

#include <string_view>

#include "harness/model/oracle.h"

namespace cc::bullet_oracle {

/// The version of Bullet this build was compiled against ("3.24").
std::string_view bullet_version();

/// Every kind's Bullet parties, each with its name, band and call, are declared in the kind's
/// unit, oracle/bullet/kinds/<kind>.cpp (none where Bullet has no fair counterpart, or none
/// wired yet: the unit says which); `crosscheck bands` lists them. A C++ exception thrown by
/// Bullet is caught and reported as a failed opinion.
class BulletSecondOpinion final : public harness::SecondOpinion {
 public:
  std::vector<harness::Opinion> opinions(const harness::Input& input) const override;
  std::vector<harness::PartyBand> parties(harness::QueryKind kind) const override;
};

}  // namespace cc::bullet_oracle
