// A kind's second opinions from ODE 0.16 in double precision (internal to oracle/ode): each
// party's name, band and call, declared together in the kind's unit, oracle/ode/kinds/<kind>.cpp,
// as Bullet's are in oracle/bullet. A kind whose unit does not define ode_parties<its input>()
// fails to link (ode_oracle.cpp asks every kind's).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "harness/model/party.h"
#include "harness/model/input.h"
#include "oracle/ode/ode_call.h"

namespace cc::ode_oracle {

using harness::answered;
using harness::Band;
using harness::BandSides;
using harness::failed;
using harness::not_applicable;
using harness::Opinion;
using harness::Party;

/// ODE's opinions on inputs of type In, in the order they are asked and stored.
template <class In>
const std::vector<Party<In>>& ode_parties();

/// A party whose call runs inside ode_call (ODE initialised, its errors a failed opinion).
template <class In, class Call>
Party<In> ode_party(std::string name, Band band, Call call) {
  return {std::move(name), band, [call](const In& in) { return ode_call([&] { return call(in); }); }};
}

}  // namespace cc::ode_oracle
