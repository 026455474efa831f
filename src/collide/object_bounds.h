// Bounds for the first level of collision detection when objects move and rotate: the cube
// that holds an object in every rotation (fitted once, moved each frame), a box fitted around the
// placed object each frame (tighter, costs a pass over its vertices), or a ball fitted once and
// moved each frame (the same in every rotation; the notes' alternative to cubes).
#pragma once

#include "collide/aabb.h"
#include "collide/mesh.h"
#include "collide/rigid_transform.h"
#include "collide/sphere.h"

namespace cc {

/// The largest distance of any vertex from the mesh's origin, rounded up so that it is never
/// below the exact distance; 0 for an empty mesh.
double rotation_radius(const Mesh& mesh);

/// The cube of half side `radius` (padded by 2^-40 of it, for rotations orthonormal within
/// 2^-48 and the rounding of apply()) around the pose's translation: it holds the mesh placed
/// by any such pose with that translation, in exact arithmetic and as apply() places it.
Aabb bounding_cube(double radius, const RigidTransform& pose);

/// The ball that holds the mesh in its own frame (fit_sphere of its vertices); radius 0 at the
/// origin for an empty mesh.
Sphere mesh_ball(const Mesh& mesh);

/// The ball placed by the pose: its centre by apply(), its radius grown by 2^-40 of it (for
/// rotations orthonormal within 2^-48) and by four times transform_error_bound for points of
/// norm1 up to |centre|_1 + 2 radius: it holds every point of the ball as apply() places it and
/// as the pose places it exactly. A ball of radius 0 grows by the transform's rounding only.
Sphere placed_ball(const Sphere& ball, const RigidTransform& pose);

/// The cube around a ball, rounded outward: it holds the ball.
Aabb box_of(const Sphere& ball);

/// The box around the mesh's vertices placed by apply(pose, v), padded by
/// transform_error_bound so that it also holds them placed exactly. An empty mesh gives the
/// degenerate box at the pose's translation.
Aabb fitted_box(const Mesh& mesh, const RigidTransform& pose);

}  // namespace cc
