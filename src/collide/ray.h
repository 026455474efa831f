// A ray or a segment: the probe that the ray tests take.
#pragma once

#include <cmath>

#include "collide/vec3.h"

namespace cc {

/// The points origin + t * dir for t in [tmin, tmax]. tmax may be +inf (a ray) and tmin may be
/// -inf; a finite tmax makes a segment. dir need not be normalised; dir = 0 is a point.
struct Ray {
  Vec3 origin;
  Vec3 dir;
  double tmin = 0;
  double tmax = INFINITY;
  friend constexpr bool operator==(const Ray&, const Ray&) = default;
};

}  // namespace cc
