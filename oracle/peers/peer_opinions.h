// Every peer library's second opinions together: FCL and libccd's (oracle/fcl), then Bullet's
// (oracle/bullet), then ODE's (oracle/ode), then Chipmunk's (oracle/chipmunk), as one
// SecondOpinion, the one the campaign, the replays, the fuzz targets and `crosscheck bands` ask.
#pragma once

#include "oracle/bullet/bullet_oracle.h"
#include "oracle/chipmunk/chipmunk_oracle.h"
#include "oracle/fcl/fcl_oracle.h"
#include "oracle/ode/ode_oracle.h"

namespace cc::peers {

class PeerOpinions final : public harness::SecondOpinion {
 public:
  /// FCL's opinions first, then Bullet's, then ODE's, then Chipmunk's, each party under its own name and band.
  std::vector<harness::Opinion> opinions(const harness::Input& input) const override;
  std::vector<harness::PartyBand> parties(harness::QueryKind kind) const override;
  int abandoned_calls() const override;

 private:
  fcl_oracle::FclSecondOpinion fcl_;
  bullet_oracle::BulletSecondOpinion bullet_;
  ode_oracle::OdeSecondOpinion ode_;
  chipmunk_oracle::ChipmunkSecondOpinion chipmunk_;
};

}  // namespace cc::peers
