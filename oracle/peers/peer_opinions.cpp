#include "oracle/peers/peer_opinions.h"

namespace cc::peers {

std::vector<harness::Opinion> PeerOpinions::opinions(const harness::Input& input) const {
  std::vector<harness::Opinion> out = fcl_.opinions(input);
  for (harness::Opinion& o : bullet_.opinions(input)) out.push_back(std::move(o));
  for (harness::Opinion& o : ode_.opinions(input)) out.push_back(std::move(o));
  for (harness::Opinion& o : chipmunk_.opinions(input)) out.push_back(std::move(o));
  return out;
}

std::vector<harness::PartyBand> PeerOpinions::parties(harness::QueryKind kind) const {
  std::vector<harness::PartyBand> out = fcl_.parties(kind);
  for (harness::PartyBand& p : bullet_.parties(kind)) out.push_back(std::move(p));
  for (harness::PartyBand& p : ode_.parties(kind)) out.push_back(std::move(p));
  for (harness::PartyBand& p : chipmunk_.parties(kind)) out.push_back(std::move(p));
  return out;
}

int PeerOpinions::abandoned_calls() const {
  return fcl_.abandoned_calls() + bullet_.abandoned_calls() + ode_.abandoned_calls() + chipmunk_.abandoned_calls();
}

}  // namespace cc::peers
