// Rigid motions: a rotation followed by a translation.
#pragma once

#include "collide/vec3.h"

namespace cc {

/// The map p -> rotation p + translation. `rotation` should be a proper rotation, orthonormal to
/// within kObbOrthonormalTolerance like an Obb's axes; the functions below apply whatever matrix
/// they are given, and their error bounds assume only |entries| <= 1 + 2^-48.
struct RigidTransform {
  Mat3 rotation;
  Vec3 translation;
  friend constexpr bool operator==(const RigidTransform&, const RigidTransform&) = default;
};

/// rotation p + translation, each component a sum3 of the three products plus the translation.
inline Vec3 apply(const RigidTransform& t, const Vec3& p) { return t.rotation * p + t.translation; }

/// The map a^-1 b: it takes coordinates in b's model frame to a's, using the transpose of a's
/// rotation as its inverse. A hierarchy walk in a's frame places b with it.
RigidTransform relative(const RigidTransform& a, const RigidTransform& b);

/// A bound on the error of each component of apply(t, p), for any p with norm1(p) <= p_norm1:
/// 2^-50 (p_norm1 + max|translation|), plus the subnormal slack (bounds::TransformBound).
double transform_error_bound(const RigidTransform& t, double p_norm1);

}  // namespace cc
