// The certified error bounds of the library's tests, each computed in one place as a struct of
// named terms. A test decides with its bound's total(); the probed versions of the tests
// (bound_records.h) hand the same structs to the harness, which measures how close the actual
// rounding of each quantity comes to each term (`crosscheck bounds`). So a change to a term
// changes what the test decides and what the harness measures alike.
//
// Every total() also holds fp::subnormal_slack, an allowance for results in the subnormal range
// where relative bounds fail; it is not a named term (it exceeds one rounding there by 2^16).
#pragma once

#include <algorithm>
#include <cmath>

#include "collide/fp.h"
#include "collide/obb.h"

namespace cc::bounds {

/// A computed parameter t (a quotient with a few roundings) moved outward: lower(t) <= t* <=
/// upper(t) whenever |t - t*| <= rounding(t), t* being its exact value. Multiplicative, so that
/// a parameter that overflowed to +-inf stays infinite (an additive pad would give inf - inf).
struct Widening {
  const char* name;  // what t is, e.g. "slab parameter"
  double relative;   // of |t|
  /// The term: how far t may be from its exact value, outside the subnormal range.
  double rounding(double t) const { return relative * std::fabs(t); }
  /// t (1 - relative) for t > 0, t (1 + relative) otherwise, less the slack: rounding is monotone,
  /// so that is the smaller of the two products (both the same double for t = +-0, NaN, +-inf).
  double lower(double t) const { return std::min(t * (1 - relative), t * (1 + relative)) - fp::subnormal_slack; }
  double upper(double t) const { return std::max(t * (1 - relative), t * (1 + relative)) + fp::subnormal_slack; }
};

/// intersect_ray_aabb (and test_ray_aabbs, and the box entries of ray_mesh): a slab parameter
/// (bound - origin) * (1 / dir) carries three roundings, at most 3.000001u relative; 8u also
/// covers the rounding of the widened value itself.
inline constexpr Widening kRaySlab{"slab parameter", 8 * fp::u};

/// intersect_ray_triangle: a slab bound over a speed, one division.
inline constexpr Widening kRayTriangleParameter{"triangle parameter", 4 * fp::u};

/// ray_mesh's volume entries: intersect_ray_aabb's 4 ulps, or a subtraction and a division.
inline constexpr Widening kRayVolumeEntry{"volume entry", 16 * fp::u};

/// sweep_obb_obb: a time (+-reach - projection) / rate, two roundings (2.0001u).
inline constexpr Widening kSweepObbTime{"obb time", 4 * fp::u};

/// sweep_aabb_aabb: a time (a.lo - b.hi) / (vb - va), three roundings (3.000001u).
inline constexpr Widening kSweepAabbTime{"aabb time", 8 * fp::u};

/// test_sphere_sphere: dist2 - reach2 (the squared offset and the squared sum of the radii, both
/// scaled to [1, 4)) is certified against total().
struct SphereBound {
  double dist2, reach2;  // as computed
  /// The difference, the squares and their sum (in any order) make dist2 within 5u of its value,
  /// the subtraction adds u of it: 8u leaves room for the bound's own rounding.
  double distance() const { return 8 * fp::u * dist2; }
  /// The sum and the square make reach2 within 3u.
  double reach() const { return 8 * fp::u * reach2; }
  double total() const { return distance() + reach(); }
};

/// fit_kdop: a projection onto a 2- or 3-term direction, s = the sum of the exact products t_i,
/// is within 2u sum |t_i| of its value; s -+ kKdopProjection sum |t_i| also covers the rounding
/// of the widened bounds.
inline constexpr double kKdopProjection = 4 * fp::u;

/// test_obb_obb and sweep_obb_obb: an axis separates when |projection| - (radius_a + radius_b)
/// exceeds total() (in the units of the axis as computed, not normalised).
struct ObbBound {
  double offset;              // |d|_1 of the centres' offset (sweep: |d|_1 + |v|_1)
  double extent_a, extent_b;  // the sums of the half extents
  /// Rounding: at most 22u offset + 8u (extents) on the worst (edge) axis; 32u covers it and the
  /// bound's own evaluation.
  double rounding() const { return 32 * fp::u * fp::sum3(offset, extent_a, extent_b); }
  /// Axes orthonormal only to within the tolerance change the radii by at most 4 tolerance
  /// (extents); 6 is used.
  double frame() const { return 6 * kObbOrthonormalTolerance * (extent_a + extent_b); }
  double total() const { return rounding() + frame() + fp::subnormal_slack; }
};

/// The separating-axis tests of the triangle queries (sat::separates): the gap between the
/// projections of two sets onto an axis is certified against total().
struct SatBound {
  double axis_norm1;                // |axis|_1
  double magnitude_a, magnitude_b;  // the sets' largest absolute coordinates
  double perturbation_per_unit;     // how far each coordinate may be off before (a change of frame)
  /// Each projected end is off by at most 3u |axis|_1 magnitude (a product and two additions per
  /// term), the gap adds one rounding: 5u covers both and the bound's own rounding.
  double projection_per_unit() const { return 5 * fp::u * (magnitude_a + magnitude_b); }
  double projection() const { return axis_norm1 * projection_per_unit(); }
  double perturbation() const { return axis_norm1 * perturbation_per_unit; }
  double total() const { return axis_norm1 * (projection_per_unit() + perturbation_per_unit) + fp::subnormal_slack; }
};

/// test_triangle_obb: the triangle taken into the box's frame (A^T (v - centre)), and the box's
/// faces there, are each off by at most total() per coordinate.
struct FrameChangeBound {
  double reach;     // the largest |v - centre|_1
  double half_sum;  // the sum of the half extents
  /// Each local coordinate is a difference, three products and two additions away from exact:
  /// 4u |v - c|_1, 5u used.
  double rounding() const { return 5 * fp::u * reach; }
  /// Axes orthonormal to within the tolerance move the box's faces in that frame by at most
  /// tolerance * half_sum; 2 used.
  double orthonormality() const { return 2 * kObbOrthonormalTolerance * half_sum; }
  double total() const { return rounding() + orthonormality() + fp::subnormal_slack; }
};

/// test_triangle_triangle: det(u, v, w) computed as (u x v) . w is nonzero beyond total().
struct IndependenceBound {
  double u_norm1, v_norm1, w_norm1;
  /// u x v is within 3u per component of |u|_1 |v|_1, the dot product adds 3u: 16u covers both
  /// and the bound's own rounding.
  double rounding() const { return 16 * fp::u * (u_norm1 * v_norm1) * w_norm1; }
  double total() const { return rounding() + fp::subnormal_slack; }
};

/// intersect_ray_triangle: one slab along `axis`, fitted to the projections of the translated
/// vertices (v - origin) and widened, and the ray's speed across it taken as an interval.
struct RayTriangleSlabBound {
  double axis_norm1;       // |axis|_1
  double reach;            // the largest |coordinate| of a translated vertex
  double speed_magnitude;  // sum |axis_i dir_i|
  bool products;           // some nonzero product axis_i dir_i (it may have underflowed)
  /// A projection axis . (v - origin) is three products and two additions (3u |axis|_1 reach)
  /// and the translation adds u |axis|_1 reach; 8u also covers the bound's own rounding.
  double projection() const { return 8 * fp::u * axis_norm1 * reach; }
  /// The speed axis . dir: 3u sum |axis_i dir_i|; 6u also covers the rounding of q -+ error.
  double speed() const { return 6 * fp::u * speed_magnitude; }
  double projection_total() const { return projection() + fp::subnormal_slack; }
  double speed_total() const { return speed() + (products ? fp::subnormal_slack : 0.0); }
};

/// ray_mesh: how far the traversal grows every volume. Half of it exceeds the distance from a
/// triangle at which intersect_ray_triangle may put its point (2^-44 R, R at most the sum of the
/// magnitudes below); the other half covers the rounding of the volume tests.
struct RayMeshPad {
  static constexpr double kFactor = 0x1p-40;
  double origin_norm1;    // |origin|_1 of the ray
  double mesh_magnitude;  // the hierarchy's magnitude (largest norm1 of a stored point)
  double origin() const { return kFactor * origin_norm1; }
  double mesh() const { return kFactor * mesh_magnitude; }
  double total() const { return kFactor * (origin_norm1 + mesh_magnitude) + fp::subnormal_slack; }
};

/// apply(t, p) (rigid_transform.h): each component within total() of rotation p + translation,
/// for any p with |p|_1 <= p_norm1, assuming only |rotation entries| <= 1 + 2^-48.
struct TransformBound {
  static constexpr double kFactor = 0x1p-50;
  double p_norm1;      // a bound on |p|_1
  double translation;  // max |translation component|
  double rotation_term() const { return kFactor * p_norm1; }
  double translation_term() const { return kFactor * translation; }
  double total() const { return kFactor * (p_norm1 + translation) + fp::subnormal_slack; }
};

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

}  // namespace cc::bounds
