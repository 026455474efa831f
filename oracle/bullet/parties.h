// A kind's second opinions from Bullet 3.24 in double precision (internal to oracle/bullet): each
// party's name, band and call, declared together in the kind's unit,
// oracle/bullet/kinds/<kind>.cpp, as the FCL parties are in oracle/fcl. A kind whose unit does
// not define bullet_parties<its input>() fails to link (bullet_oracle.cpp asks every kind's).
#pragma once

#include <vector>

#include "harness/model/party.h"
#include "harness/model/input.h"

namespace cc::bullet_oracle {

using harness::answered;
using harness::Band;
using harness::BandSides;
using harness::failed;
using harness::not_applicable;
using harness::Opinion;
using harness::Party;

/// Bullet's opinions on inputs of type In, in the order they are asked and stored.
template <class In>
const std::vector<Party<In>>& bullet_parties();

}  // namespace cc::bullet_oracle
