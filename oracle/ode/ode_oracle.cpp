#include "oracle/ode/ode_oracle.h"

#include "oracle/ode/parties.h"

namespace cc::ode_oracle {

std::string_view ode_version() { return CROSSCHECK_ODE_VERSION; }

std::vector<harness::Opinion> OdeSecondOpinion::opinions(const harness::Input& input) const {
  return std::visit([]<class In>(const In& in) { return harness::ask_parties(ode_parties<In>(), in); }, input);
}

std::vector<harness::PartyBand> OdeSecondOpinion::parties(harness::QueryKind kind) const {
  return harness::with_kind(kind, []<class In>() {
    std::vector<harness::PartyBand> out;
    for (const Party<In>& p : ode_parties<In>()) out.push_back({p.name, p.band});
    return out;
  });
}

}  // namespace cc::ode_oracle
