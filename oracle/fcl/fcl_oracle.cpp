#include "oracle/fcl/fcl_oracle.h"

#include <fcl/config.h>

#include <stdexcept>

#include "oracle/fcl/parties.h"
#include "oracle/fcl/time_limit.h"

namespace cc::fcl_oracle {

std::string_view fcl_version() { return FCL_VERSION; }

FclSecondOpinion::FclSecondOpinion() {
  if (!fcl_supports_used_pairs()) {
    throw std::runtime_error("FCL's collision matrix lacks sphere-sphere or box-box: its answers would read as misses");
  }
}

std::vector<Opinion> FclSecondOpinion::opinions(const harness::Input& input) const {
  return std::visit([]<class In>(const In& in) { return harness::ask_parties(fcl_parties<In>(), in); }, input);
}

std::vector<harness::PartyBand> FclSecondOpinion::parties(harness::QueryKind kind) const {
  return harness::with_kind(kind, []<class In>() {
    std::vector<harness::PartyBand> out;
    for (const Party<In>& p : fcl_parties<In>()) out.push_back({p.name, p.band});
    return out;
  });
}

int FclSecondOpinion::abandoned_calls() const { return fcl_oracle::abandoned_calls(); }

}  // namespace cc::fcl_oracle
