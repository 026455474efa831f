#include "tool/oracles.h"

#include "oracle/exact/exact_reference.h"
#include "oracle/peers/peer_opinions.h"

namespace cc::tool {

harness::Oracles make_oracles() {
  return {[] { return std::make_unique<exact::ExactRationalReference>(); },
          [] { return std::make_unique<peers::PeerOpinions>(); }};
}

}  // namespace cc::tool
