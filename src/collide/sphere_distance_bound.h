// The bounds of distance_sphere_sphere and distance_sphere_obb (sphere_distance.h), term by term.
#pragma once

#include "collide/fp.h"
#include "collide/obb.h"
#include "collide/record_sink.h"
#include "collide/separation.h"
#include "collide/sphere.h"

namespace cc::bounds {

/// distance_sphere_sphere, with n the computed |d| (d = b.center - a.center) and reach the
/// computed a.radius + b.radius.
struct SphereDistanceBound {
  double n, reach, center_magnitude, radius;
  /// d's components round once (u |d|), the sum of squares 3u and the square root u/2 more of
  /// |d|, the reach u of itself, the difference u of both: about 5.1u |d| + 2.1u reach.
  double rounding() const { return 8 * fp::u * (n + reach); }
  double distance() const { return rounding() + fp::subnormal_slack; }
  /// The unit direction d/n within 7u of its length (d's rounding, the length's 2.6u, the
  /// reciprocal and the product); a witness c + r w rounds u of r w and u of the sum per
  /// coordinate: within 11u r + 2u |c|_inf of the sphere's boundary.
  double point_rounding() const { return 16 * fp::u * (center_magnitude + radius); }
  double point() const { return point_rounding() + fp::subnormal_slack; }
};

/// distance_sphere_obb, with offset = |d|_1 (d = a.center - b.center), half = |b.half|_1.
struct SphereObbDistanceBound {
  double offset, half, radius, center_magnitude;
  /// The box's coordinates of d (one rounding of d and a three-term dot: 4u of |d| each), the
  /// difference from the clamped point or the face (u), its length (2.6u) and the radius' (u):
  /// within 7.2u |d| + 4.6u (|d| + |half|) + u r.
  double rounding() const { return 16 * fp::u * fp::sum3(offset, half, radius); }
  /// Axes orthonormal to within eta: the coordinates d's transpose product gives differ from
  /// its coordinates in the (skew) frame by 3 eta |d|_inf each, and lengths measured in the
  /// frame differ from the world's by 1.5 eta: within 7 eta (|d|_1 + |half|_1).
  double frame() const { return 8 * kObbOrthonormalTolerance * (offset + half); }
  double distance() const { return fp::sum3(rounding(), frame(), fp::subnormal_slack); }
  /// The box's witness c + A q rounds 3u of |q| and u of the sum per coordinate; the ball's
  /// s - r w as in the spheres' bound, with w's length within 1.5 eta + 6u of 1.
  double point_rounding() const { return 16 * fp::u * (center_magnitude + fp::sum3(offset, half, radius)); }
  double point() const {
    return fp::sum3(point_rounding(), 4 * kObbOrthonormalTolerance * fp::sum3(radius, offset, half), fp::subnormal_slack);
  }
};

/// A call of distance_sphere_sphere and its answer, as computed.
struct SphereSeparation {
  Sphere a, b;
  Separation answer;
  SphereDistanceBound bound;
};

/// A call of distance_sphere_obb and its answer, as computed.
struct SphereObbSeparation {
  Sphere a;
  Obb b;
  Separation answer;
  SphereObbDistanceBound bound;
};

}  // namespace cc::bounds

namespace cc {

/// The same as their plain versions (sphere_distance.h), recording the call and its bounds into
/// `records` (bound_records.h); the same answer, bit for bit.
Separation distance_sphere_sphere(const Sphere& a, const Sphere& b, bounds::Records& records);
Separation distance_sphere_obb(const Sphere& a, const Obb& b, bounds::Records& records);

}  // namespace cc
