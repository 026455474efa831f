// Rays and segments against triangle meshes through a bounding-volume hierarchy: the closest
// hit, or any hit.
#pragma once

#include <cstdint>

#include "collide/bvh.h"
#include "collide/ray_triangle.h"

namespace cc {

/// What a ray query cost.
struct RayMeshCounters {
  std::uint64_t bv_tests = 0;        // ray-volume tests
  std::uint64_t triangle_tests = 0;  // ray-triangle tests (intersect_ray_triangle)
  friend bool operator==(const RayMeshCounters&, const RayMeshCounters&) = default;
};

/// Where a ray meets a mesh: the parameter t and the face (an index into Mesh::faces) that
/// intersect_ray_triangle reports there.
struct RayMeshHit {
  bool hit = false;
  double t = 0;
  std::uint32_t face = 0;
  RayMeshCounters counters;
};

/// The first hit of the ray on the mesh of the hierarchy: of the faces that
/// intersect_ray_triangle reports hit, the one with the smallest t, and among equal t the one
/// with the smallest face index. So the answer (hit, t, face) does not depend on the volume
/// type or the build: it is ray_mesh_brute_force's. Conservative and tolerant as
/// intersect_ray_triangle is (a face that the ray touches in exact arithmetic is hit; t is
/// never later than the exact first point).
///  - Traversal: nodes are descended nearer child first (by the entry of ray_volume_entry)
///    and a node is pruned only when its entry exceeds the best t found. The entry is at most
///    every t that intersect_ray_triangle reports for a triangle below the node (see
///    ray_volume_entry), so pruning loses no hit, and a tie at the entry is still descended.
///  - Surfaces only: a ray starting inside a closed mesh hits its inner side; a mesh that the
///    ray does not reach gives no hit. An empty hierarchy gives no hit.
///  - Domain: that of intersect_ray_triangle and of a valid mesh (mesh_problem) of magnitude
///    at most 2^300. A NaN or infinite ray gives no hit.
template <class BV>
RayMeshHit ray_mesh_closest(const Bvh<BV>& bvh, const Ray& ray);

/// Some hit of the ray on the mesh: the first face found in the same near-first traversal
/// without pruning by t (it stops there), with its t. Hits exactly when ray_mesh_closest does.
template <class BV>
RayMeshHit ray_mesh_any(const Bvh<BV>& bvh, const Ray& ray);

/// The closest hit without a hierarchy: every face by intersect_ray_triangle, the smallest t
/// and among equal t the smallest face index. bv_tests stays 0.
RayMeshHit ray_mesh_brute_force(const Mesh& mesh, const Ray& ray);

/// The volume test of the traversal: whether the ray may reach a triangle inside a volume
/// and, if so, a lower bound on the t at which it does.
struct RayVolumeEntry {
  bool hit = false;
  double t = 0;  // at least tmin
};

/// How far the traversal grows every volume: 2^-40 (|origin|_1 + bvh.magnitude). Half of it
/// exceeds the distance from a triangle at which intersect_ray_triangle may put its point
/// (kRayTriangleTolerance R, with R at most that sum); the other half covers the rounding of
/// the volume tests below (moving the ray into an OBB's frame, the deviation of its axes from
/// orthonormal, a k-DOP's slab parameters) at every point of the ray near the mesh.
template <class BV>
double ray_mesh_pad(const Bvh<BV>& bvh, const Ray& ray);

/// The ray against a volume grown by pad (up to rounding). For a volume of `bvh` and
/// pad = ray_mesh_pad(bvh, ray), rounding included: a miss only when,
/// in exact arithmetic, no point of the ray (t in [tmin, tmax]) lies within pad / 2 of the
/// volume; on a hit, tmin <= t <= the parameter of the first such point. Hence a triangle inside
/// the volume that intersect_ray_triangle reports hit at t makes the entry a hit at most t.
///  - Aabb: intersect_ray_aabb against the grown box, its t_enter lowered by its 4 ulps.
///  - Obb: the ray moved into the box's frame (origin - center and dir by the transposed
///    axes), then as an Aabb.
///  - Kdop<K>: the slabs lo <= n . p <= hi of its k/2 directions n, each grown by pad |n|_1;
///    a slab with n . dir == 0 (as computed) is parallel, and the origin decides.
///  - Sphere: the cube around the ball, as an Aabb (an entry never later than the ball's).
///  - Every test scales dir by a power of two first, so a huge or tiny dir is as good as a unit
///    one. NaN or infinite input, tmin > tmax, or a negative pad: no hit.
template <class BV>
RayVolumeEntry ray_volume_entry(const BV& volume, const Ray& ray, double pad);

}  // namespace cc
