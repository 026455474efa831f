// sphere_sphere: two spheres, test_sphere_sphere.
#pragma once

#include "collide/sphere.h"

namespace cc::harness {

struct SphereSphereInput {
  Sphere a, b;
  friend bool operator==(const SphereSphereInput&, const SphereSphereInput&) = default;
};

}  // namespace cc::harness
