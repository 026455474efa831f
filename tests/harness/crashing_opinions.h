// For the tests of a case's process dying: second opinions that crash the process they are
// asked in, and an input every party answers.
#pragma once

#include <csignal>
#include <vector>

#include "harness/model/input.h"
#include "harness/model/oracle.h"

namespace cc::harness {

/// Two parties, with an exact band, that raise SIGSEGV when asked.
class CrashingOpinions final : public SecondOpinion {
 public:
  static constexpr Band kBand{0, BandSides::exact, 0, "comparisons of inputs only: exact"};
  std::vector<Opinion> opinions(const Input&) const override {
    std::raise(SIGSEGV);
    return {};
  }
  std::vector<PartyBand> parties(QueryKind) const override { return {{"fcl.AABBd::overlap", kBand}, {"bullet.x", kBand}}; }
};

/// Two overlapping boxes.
inline const Input kOverlapping = AabbAabbInput{{{0, 0, 0}, {1, 1, 1}}, {{0.5, 0.5, 0.5}, {2, 2, 2}}};

}  // namespace cc::harness
