// Boxes for the first level of collision detection when objects move and rotate: either the
// cube that holds an object in every rotation (fitted once, moved each frame), or a box fitted
// around the placed object each frame (tighter, costs a pass over its vertices).
#pragma once

#include "collide/aabb.h"
#include "collide/mesh.h"
#include "collide/rigid_transform.h"

namespace cc {

/// The largest distance of any vertex from the mesh's origin, rounded up so that it is never
/// below the exact distance; 0 for an empty mesh.
double rotation_radius(const Mesh& mesh);

/// The cube of half side `radius` (padded by 2^-40 of it, for rotations orthonormal within
/// 2^-48 and the rounding of apply()) around the pose's translation: it holds the mesh placed
/// by any such pose with that translation, in exact arithmetic and as apply() places it.
Aabb bounding_cube(double radius, const RigidTransform& pose);

/// The box around the mesh's vertices placed by apply(pose, v), padded by
/// transform_error_bound so that it also holds them placed exactly. An empty mesh gives the
/// degenerate box at the pose's translation.
Aabb fitted_box(const Mesh& mesh, const RigidTransform& pose);

}  // namespace cc
