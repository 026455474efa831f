// The input of sphere_sphere and its fields; the kind's unit is src/harness/kinds/sphere_sphere.h.
#pragma once

#include "harness/model/parts.h"

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
