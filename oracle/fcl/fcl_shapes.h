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

/// The bands of distance queries: a closed form in floating point with no tolerance (rounding
/// only, through the placements' products), and GJK and EPA (libccd's and FCL's own), whose
/// tolerance (1e-6) is absolute: the band it means at unit scale.
inline constexpr harness::Band kClosedFormDistanceBand{0x1p-40, harness::BandSides::two_sided, 0x1p-40,
                                                       "a closed form in floating point with no tolerance: rounding only"};
inline constexpr harness::Band kGjkDistanceBand{0x1p-19, harness::BandSides::two_sided, 0x1p-19,
                                                "GJK's and EPA's distance tolerance (1e-6, absolute): the band it means at unit scale"};

/// How distance() is asked: its solver, and whether for a signed distance.
struct FclDistanceRequest {
  bool indep_solver = false;     // GJKSolver_indep, else GJKSolver_libccd (FCL's default)
  bool signed_distance = false;  // DistanceRequest::enable_signed_distance
};

/// FCL's distance() on two placed shapes with nearest points, under the libccd time limit (a
/// failed assertion in its libccd code is a failure, not the end of the process):
///  - unsigned: the distance and both points where it finds them apart, else (it gives -1) a hit
///    with no distance;
///  - signed, libccd: the signed distance and both points (GJK, or EPA where they overlap);
///  - signed, indep: apart as unsigned; overlapping, minus the deepest contact's depth alone, as
///    its points are then the contact's position twice (distance.h: "not guaranteed to be on the
///    surface").
/// The caller does not ask on a NaN or infinite number, on which libccd reads memory it never set.
harness::Opinion fcl_distance(const fcl::CollisionGeometryd& a, const fcl::Transform3d& ta, const fcl::CollisionGeometryd& b,
                              const fcl::Transform3d& tb, FclDistanceRequest how);

}  // namespace cc::fcl_oracle
