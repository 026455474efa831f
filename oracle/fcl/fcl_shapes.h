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

/// A GJK solver of FCL's narrow phase: GJKSolver_libccd or GJKSolver_indep.
enum class GjkSolver { libccd, indep };

/// The solver's shapeDistance on two triangles at identity placements (its generic GJK: FCL
/// 0.7's distance() has no function for a pair of TriangleP), under the libccd time limit: the
/// distance and the two points (params, Judged::distance), or, where the solver finds them in
/// collision (it then gives -1), a hit with no distance. Not applicable to a NaN or infinite
/// coordinate.
harness::Opinion fcl_gjk_distance(const Triangle& a, const Triangle& b, GjkSolver solver);

}  // namespace cc::fcl_oracle
