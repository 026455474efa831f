#include "tool/oracles.h"

#include "oracle/exact/exact_reference.h"
#include "oracle/fcl/fcl_oracle.h"

namespace cc::tool {

harness::Oracles make_oracles() {
  return {[] { return std::make_unique<exact::ExactRationalReference>(); },
          [] { return std::make_unique<fcl_oracle::FclSecondOpinion>(); }};
}

}  // namespace cc::tool
