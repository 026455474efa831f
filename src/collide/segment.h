// Segments.
#pragma once

#include "collide/vec3.h"

namespace cc {

/// The closed segment from a to b; a == b is a point.
struct Segment {
  Vec3 a, b;
  friend constexpr bool operator==(const Segment&, const Segment&) = default;
};

/// True when no coordinate is NaN or infinite.
inline bool finite(const Segment& s) { return finite(s.a) && finite(s.b); }

}  // namespace cc
