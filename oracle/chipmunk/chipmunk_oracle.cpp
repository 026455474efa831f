#include "oracle/chipmunk/chipmunk_oracle.h"

#include <chipmunk/chipmunk.h>

#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {

std::string_view chipmunk_version() { return CROSSCHECK_CHIPMUNK_VERSION; }

std::string_view chipmunk_library_version() { return cpVersionString; }

std::vector<harness::Opinion> ChipmunkSecondOpinion::opinions(const harness::Input& input) const {
  return std::visit([]<class In>(const In& in) { return harness::ask_parties(chipmunk_parties<In>(), in); }, input);
}

std::vector<harness::PartyBand> ChipmunkSecondOpinion::parties(harness::QueryKind kind) const {
  return harness::with_kind(kind, []<class In>() {
    std::vector<harness::PartyBand> out;
    for (const Party<In>& p : chipmunk_parties<In>()) out.push_back({p.name, p.band});
    return out;
  });
}

}  // namespace cc::chipmunk_oracle
