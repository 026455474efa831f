// The input of disc_walls and its fields; the kind's unit is src/harness/kinds/disc_walls.h.
#pragma once

#include <vector>

#include "harness/model/parts.h"

namespace cc::harness {

/// A disc and the walls of a maze around it.
struct DiscWallsInput {
  Disc disc;
  std::vector<Wall> walls;
  friend bool operator==(const DiscWallsInput&, const DiscWallsInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record: the disc (centre, radius),
/// then the walls (each a, b).
template <>
struct Fields<DiscWallsInput> {
  static constexpr auto list = std::tuple{field<&DiscWallsInput::disc>("disc"), field<&DiscWallsInput::walls>("walls")};
};

}  // namespace cc::harness
