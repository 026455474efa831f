// The bounds of intersect_ray_triangle (ray_triangle.h), and its record.
#pragma once

#include "collide/fp.h"
#include "collide/ray_triangle.h"
#include "collide/record_sink.h"
#include "collide/triangle.h"
#include "collide/widening.h"

namespace cc::bounds {

/// A slab bound over a speed, one division.
inline constexpr Widening kRayTriangleParameter{"triangle parameter", 4 * fp::u};

/// One slab along `axis`, fitted to the projections of the translated vertices (v - origin) and
/// widened, and the ray's speed across it taken as an interval.
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

/// One slab: the translated vertices (triangle - origin) and their projections onto `axis`, and
/// the speed of the scaled direction across it, as computed.
struct RayTriangleSlab {
  Vec3 origin;
  Triangle triangle, translated;
  Vec3 dir_scaled;
  Vec3 axis;
  double projections[3] = {0, 0, 0};
  double speed = 0;
  RayTriangleSlabBound bound;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (ray_triangle.h), recording its certified quantities into `records`
/// (bound_records.h); the same answer, bit for bit.
RayTriangleHit intersect_ray_triangle(const Ray& ray, const Triangle& triangle, bounds::Records& records);

}  // namespace cc
