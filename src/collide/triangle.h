// Triangles.
#pragma once

#include <array>

#include "collide/vec3.h"

namespace cc {

/// The closed triangle with vertices v[0], v[1], v[2]. Degenerate triangles are valid: with
/// collinear vertices it is a segment, with three equal vertices a point.
struct Triangle {
  std::array<Vec3, 3> v;
  friend constexpr bool operator==(const Triangle&, const Triangle&) = default;
};

/// True when no coordinate is NaN or infinite.
inline bool finite(const Triangle& t) { return finite(t.v[0]) && finite(t.v[1]) && finite(t.v[2]); }

}  // namespace cc
