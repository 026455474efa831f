// Rotation matrices for the generators, from exact ones (signed permutations, dyadic small
// rotations) to general ones built in floating point, and matrices outside the OBB contract.
#pragma once

#include <cstddef>

#include "collide/vec3.h"
#include "harness/generation/values.h"

namespace cc::harness {

/// A rotation: identity, a signed permutation (exactly orthonormal), a small rotation about a
/// coordinate axis with dyadic entries (orthonormal to within 2^-50), a rotation about an axis
/// by a generic angle, or a random quaternion's matrix (orthonormal to a few u; some components 0).
Mat3 draw_rotation(ValueSource& values);

/// A matrix close to `base`: equal, an entry nudged by a few ULPs, or composed with a tiny
/// rotation; for nearly parallel edges.
Mat3 draw_rotation_near(ValueSource& values, const Mat3& base);

/// A matrix outside the OBB contract: scaled or sheared beyond the orthonormality tolerance.
Mat3 draw_non_orthonormal(ValueSource& values);

/// The rotation of the unit quaternion (w, x, y, z) / |(w, x, y, z)| (not all zero).
Mat3 from_quaternion(double w, double x, double y, double z);

/// A fixed table of 32 rotations: the 24 rotations of the cube (signed permutations with
/// determinant 1, exact) and 8 generic ones; for records that name a rotation by a byte.
const Mat3& table_rotation(std::size_t index);

/// The product a * b.
Mat3 multiply(const Mat3& a, const Mat3& b);

}  // namespace cc::harness
