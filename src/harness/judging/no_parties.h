// A peer that has no parties for a kind says so in one line (for the kinds it has no counterpart
// for), instead of a unit that defines an empty list.
#pragma once

#include <vector>

#include "harness/model/party.h"

/// Declares in one line that a peer has no parties for a kind: `parties_function` (the peer's
/// template, e.g. chipmunk_parties) for the kind's input (Name##Input) gives none. `kind` (its
/// name) and `why` (a sentence) are for the reader and `crosscheck kind-files`; a peer's lines
/// are in its oracle/<peer>/no_parties.cpp, and CMake then builds no unit of the kind for it.
#define CC_NO_PARTIES(parties_function, kind, Name, why)                                      \
  template <>                                                                                \
  const std::vector<::cc::harness::Party<::cc::harness::Name##Input>>& parties_function() { \
    static const std::vector<::cc::harness::Party<::cc::harness::Name##Input>> none;         \
    return none;                                                                             \
  }
