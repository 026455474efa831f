// FCL's collide() on two shapes and its GJK solvers' distance, for the kinds' units (internal to
// oracle/fcl).
#pragma once

#include <fcl/geometry/collision_geometry.h>

#include "collide/triangle.h"
#include "harness/model/party.h"
#include "oracle/fcl/convert.h"

namespace cc::fcl_oracle {

/// Whether FCL's collide() (libccd solver, first contact only) finds the shapes in contact.
bool fcl_collide(const fcl::CollisionGeometryd& a, const fcl::Transform3d& ta, const fcl::CollisionGeometryd& b,
                 const fcl::Transform3d& tb);

/// GJKSolver_indep's shapeDistance on two triangles at identity placements (its generic GJK:
/// FCL 0.7's distance() has no function for a pair of TriangleP, and GJKSolver_libccd's crashes
/// on them), under the libccd time limit: the distance and the two points (params,
/// Judged::distance), or, where it finds them in collision (it then gives -1), a hit with no
/// distance. Not asked on a NaN or infinite coordinate, as the libccd solver is not.
harness::Opinion fcl_indep_distance(const Triangle& a, const Triangle& b);

}  // namespace cc::fcl_oracle
