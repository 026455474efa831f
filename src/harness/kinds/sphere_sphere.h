// sphere_sphere: two spheres, test_sphere_sphere.
#pragma once

#include "harness/formats/parts.h"

namespace cc::harness {

struct SphereSphereInput {
  Sphere a, b;
  friend bool operator==(const SphereSphereInput&, const SphereSphereInput&) = default;
};

/// Its fields, in the order of the case file and of the fuzz record.
template <>
struct Fields<SphereSphereInput> {
  static constexpr auto list = std::tuple{field<&SphereSphereInput::a>("a"), field<&SphereSphereInput::b>("b")};
};

}  // namespace cc::harness
