// The input of broadphase and its fields; the kind's unit is src/harness/kinds/broadphase.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

/// Boxes added, moved and removed frame by frame (see BoxFrames; a box not yet added, or
/// removed, is nothing). The answer: the overlapping pairs (i, j), i < j, of each frame.
struct BroadphaseInput {
  BoxFrames frames;
  friend bool operator==(const BroadphaseInput&, const BroadphaseInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<BroadphaseInput> {
  static constexpr auto list = std::tuple{field<&BroadphaseInput::frames>("frames")};
};

}  // namespace cc::harness
