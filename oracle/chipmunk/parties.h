// A kind's second opinions from Chipmunk 7 in double precision (internal to oracle/chipmunk):
// each party's name, band and call, declared together in the kind's unit,
// oracle/chipmunk/kinds/<kind>.cpp, as ODE's are in oracle/ode. A kind whose unit does not
// define chipmunk_parties<its input>() fails to link (chipmunk_oracle.cpp asks every kind's).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "harness/model/party.h"
#include "harness/model/input.h"
#include "oracle/chipmunk/chipmunk_call.h"

namespace cc::chipmunk_oracle {

using harness::answered;
using harness::Band;
using harness::BandSides;
using harness::failed;
using harness::not_applicable;
using harness::Opinion;
using harness::Party;

/// Chipmunk's opinions on inputs of type In, in the order they are asked and stored.
template <class In>
const std::vector<Party<In>>& chipmunk_parties();

/// A party whose call runs inside chipmunk_call (a failed assertion a failed opinion).
template <class In, class Call>
Party<In> chipmunk_party(std::string name, Band band, Call call) {
  return {std::move(name), band, [call](const In& in) { return chipmunk_call([&] { return call(in); }); }};
}

}  // namespace cc::chipmunk_oracle
