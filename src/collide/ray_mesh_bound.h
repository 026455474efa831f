// The bounds of ray_mesh (ray_mesh.h): its volume entries and the pad of its traversal, and the
// record of a face hit.
#pragma once

#include "collide/fp.h"
#include "collide/ray.h"
#include "collide/ray_mesh.h"
#include "collide/record_sink.h"
#include "collide/triangle.h"
#include "collide/widening.h"

namespace cc::bounds {

/// A volume entry: intersect_ray_aabb's 4 ulps, or a subtraction and a division.
inline constexpr Widening kRayVolumeEntry{"volume entry", 16 * fp::u};

/// How far the traversal grows every volume. Half of it exceeds the distance from a triangle at
/// which intersect_ray_triangle may put its point (2^-44 R, R at most the sum of the magnitudes
/// below); the other half covers the rounding of the volume tests.
struct RayMeshPad {
  static constexpr double kFactor = 0x1p-40;
  double origin_norm1;    // |origin|_1 of the ray
  double mesh_magnitude;  // the hierarchy's magnitude (largest norm1 of a stored point)
  double origin() const { return kFactor * origin_norm1; }
  double mesh() const { return kFactor * mesh_magnitude; }
  double total() const { return kFactor * (origin_norm1 + mesh_magnitude) + fp::subnormal_slack; }
};

/// A face hit at t (intersect_ray_triangle's answer), and the traversal's pad.
struct RayMeshFaceHit {
  Ray ray;
  Triangle triangle;
  double t = 0;
  RayMeshPad pad;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (ray_mesh.h), recording its certified quantities into `records`
/// (bound_records.h); the same answer, bit for bit.
template <class BV>
RayMeshHit ray_mesh_closest(const Bvh<BV>& bvh, const Ray& ray, bounds::Records& records);

}  // namespace cc
