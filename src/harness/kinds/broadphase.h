// broadphase: the overlapping pairs of a set of boxes, frame by frame (ColumnSweep).
#pragma once

#include <optional>
#include <vector>

#include "collide/aabb.h"

namespace cc::harness {

/// A set of boxes over a sequence of frames: frames[f][i] is box i in frame f, or nothing when
/// box i is not in the scene then (not yet added, or removed). Every frame has the same number
/// of slots. The answer: the overlapping pairs (i, j), i < j, of each frame.
struct BroadphaseInput {
  std::vector<std::vector<std::optional<Aabb>>> frames;
  friend bool operator==(const BroadphaseInput&, const BroadphaseInput&) = default;
};

}  // namespace cc::harness
