// The bounds of the objects' bounds (object_bounds.h): bounding_cube's half side and
// rotation_radius's pad, and the records of fitted_box, rotation_radius and bounding_cube.
#pragma once

#include "collide/aabb.h"
#include "collide/object_bounds.h"
#include "collide/record_sink.h"
#include "collide/rigid_transform.h"
#include "collide/transform_bound.h"

namespace cc::bounds {

/// bounding_cube: the cube of half side radius + these terms around the translation holds the
/// mesh placed by any rotation orthonormal to within the tolerance with that translation (a
/// vertex v rotated reaches at most (1 + 1.5 tolerance) |v| on an axis), exactly and as apply()
/// places it.
struct CubeBound {
  double radius;
  TransformBound transform;  // apply()'s rounding, for points of |p|_1 <= 3 radius
  double orthonormality() const { return radius * 0x1p-40; }
  double half_side() const { return (radius + orthonormality()) + transform.total(); }
};

/// rotation_radius: the largest sqrt(v . v), moved up by 2^-50 of it (the dot product and the
/// square root round by less than 2^-51 in all).
inline double padded_radius(double root) { return root * (1 + 0x1p-50); }

/// apply(pose, point) as fitted_box computes it: the rotated point, then the placed one.
struct Placement {
  RigidTransform pose;
  Vec3 point, rotated, placed;
  TransformBound bound;
};

/// rotation_radius: sqrt(vertex . vertex) as computed, and padded_radius of it (the result takes
/// the largest).
struct RadiusRoot {
  Vec3 vertex;
  double root = 0, padded = 0;
};

/// bounding_cube: the pose, the terms of the cube's half side, and the cube.
struct Cube {
  RigidTransform pose;
  CubeBound bound;
  Aabb cube;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (object_bounds.h), recording its certified quantities into
/// `records` (bound_records.h); the same answer, bit for bit.
double rotation_radius(const Mesh& mesh, bounds::Records& records);

/// The same as its plain version (object_bounds.h), recording its certified quantities into
/// `records` (bound_records.h); the same answer, bit for bit.
Aabb bounding_cube(double radius, const RigidTransform& pose, bounds::Records& records);

/// The same as its plain version (object_bounds.h), recording its certified quantities into
/// `records` (bound_records.h); the same answer, bit for bit.
Aabb fitted_box(const Mesh& mesh, const RigidTransform& pose, bounds::Records& records);

}  // namespace cc
