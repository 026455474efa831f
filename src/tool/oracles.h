// The oracles the tool wires into the harness: the exact rational reference and the peers
// (FCL/libccd, Bullet and ODE).
#pragma once

#include "harness/processes/campaign.h"

namespace cc::tool {

harness::Oracles make_oracles();

}  // namespace cc::tool
