// A rotation for tests: about x by a, z by b and y by c, in that order (y first), each
// orthonormal up to rounding, as a generic placement of shapes.
#pragma once

#include <cmath>

#include "collide/vec3.h"

namespace cc::test {

inline Mat3 rotation(double a, double b, double c) {
  const Mat3 x = Mat3::from_columns({1, 0, 0}, {0, std::cos(a), std::sin(a)}, {0, -std::sin(a), std::cos(a)});
  const Mat3 z = Mat3::from_columns({std::cos(b), std::sin(b), 0}, {-std::sin(b), std::cos(b), 0}, {0, 0, 1});
  const Mat3 y = Mat3::from_columns({std::cos(c), 0, -std::sin(c)}, {0, 1, 0}, {std::sin(c), 0, std::cos(c)});
  Mat3 r;
  for (int k = 0; k < 3; ++k) r.col[k] = x * (z * (y * Mat3::identity().col[k]));
  return r;
}

}  // namespace cc::test
