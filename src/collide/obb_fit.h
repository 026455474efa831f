// Fitting an oriented bounding box to points, the OBBTree way.
#pragma once

#include <optional>
#include <span>

#include "collide/convex_hull.h"
#include "collide/obb.h"

namespace cc {

/// The box of Gottschalk, Lin and Manocha (OBBTree, 1996): its axes are the eigenvectors of the
/// covariance of the convex hull's surface (fast_convex_hull's; each hull triangle weighted by its
/// area, Eigen's self-adjoint solver; three points: triangle_axes), its extents those of the
/// points along the axes.
///  - Conservative: every point lies in the box in exact arithmetic. The half extents are
///    widened by 2^-44 of the points' magnitude (the sum over the coordinates of their largest
///    magnitude, at least every point's norm1), which covers the rounding of the projections
///    and the axes' deviation from orthonormal.
///  - Axes: right-handed and orthonormal to within 2^-50 (well within kObbOrthonormalTolerance).
///  - Flat points (a triangle, a plate): the polygon's covariance, so one axis is the normal.
///    Collinear or coincident points: the covariance of the points themselves; a single point
///    gives the identity axes and (padded) zero extents.
///  - Points must be finite and not empty.
Obb fit_obb(std::span<const Vec3> points);

/// The two halves of fit_obb, for callers that have the hull already: the axes from the
/// surface covariance of `hull` (a convex hull of `points`), ...
Mat3 obb_axes(std::span<const Vec3> points, const ConvexHull& hull);
/// ... and the smallest box with those axes that contains the points (padded as above).
Obb fit_obb(const Mat3& axes, std::span<const Vec3> points);

/// obb_axes for one triangle (whose hull is the triangle itself, on both sides), in closed form:
/// about the centroid, a triangle's surface covariance is a twelfth of its vertices' and has the
/// normal as an eigenvector, so the axes are the principal axes of the vertices in the plane (the
/// larger variance first) and the normal, right-handed and orthonormal to within 2^-50. Nothing
/// for a triangle so thin that its plane is ill-determined (twice its area at most 2^-20 of its
/// longest edge squared, collinear and repeated vertices included): use obb_axes.
std::optional<Mat3> triangle_axes(const Vec3& p, const Vec3& q, const Vec3& r);

/// Right-handed orthonormal axes (to within 2^-50) along the eigenvectors of the symmetric
/// matrix with entries xx, yy, zz, xy, yz, zx (a covariance), the largest eigenvalue's first,
/// then the middle one's: the identity for the zero matrix or when no eigenvectors are found.
Mat3 principal_axes(const std::array<double, 6>& symmetric);

/// A box with the given axes that holds both boxes (each box's points, in exact arithmetic): along
/// each axis u a box reaches u . center +- sum_j |u . axis_j| half_j, and the extents are padded
/// as fit_obb pads them, with the largest norm1 of a point of either box as the magnitude.
Obb merge_obbs(const Obb& a, const Obb& b, const Mat3& axes);

}  // namespace cc
