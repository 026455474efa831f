// Spheres.
#pragma once

#include "collide/vec3.h"

namespace cc {

/// The closed ball of the given radius around the centre. Radius 0 is a point.
struct Sphere {
  Vec3 center;
  double radius = 0;
  friend constexpr bool operator==(const Sphere&, const Sphere&) = default;
};

/// True when the closed balls share a point: |a.center - b.center| <= a.radius + b.radius.
/// Conservative: evaluated in floating point, it answers true whenever the exact answer is
/// true (touching included), and may answer true for balls whose surfaces are apart by less
/// than 2^-46 of the largest input magnitude. Symmetric in a and b bit for bit.
///  - Domain: finite inputs of magnitude at most 2^500, radii >= 0.
///  - NaN or infinite input, or a negative radius: false.
bool test_sphere_sphere(const Sphere& a, const Sphere& b);

}  // namespace cc
