// The distance between two placed meshes through their hierarchies: a traversal that prunes a
// pair of nodes when a lower bound on their volumes' distance exceeds the best answer so far.
#pragma once

#include <cstdint>
#include <limits>
#include <utility>

#include "collide/bvh.h"
#include "collide/mesh.h"
#include "collide/rigid_transform.h"
#include "collide/separation.h"

namespace cc {

/// What a distance query cost.
struct DistanceCounters {
  std::uint64_t bv_tests = 0;         // lower bounds computed on a pair of volumes
  std::uint64_t primitive_tests = 0;  // triangle-triangle distances computed
  friend bool operator==(const DistanceCounters&, const DistanceCounters&) = default;
};

/// The faces a mesh distance's witnesses lie on; kNoFace for a mesh without triangles.
inline constexpr std::uint32_t kNoFace = std::numeric_limits<std::uint32_t>::max();

struct MeshSeparation {
  /// In world coordinates: the distance (>= 0) and witnesses on_a on a's surface, on_b on b's.
  Separation separation;
  /// The witnesses' faces: (face of a's mesh, face of b's mesh).
  std::pair<std::uint32_t, std::uint32_t> faces{kNoFace, kNoFace};
  DistanceCounters counters;
};

/// The distance between the surfaces of a placed by pose_a and b placed by pose_b (each vertex
/// v at pose.rotation v + pose.translation, exactly), and a nearly closest pair of points.
/// Surfaces only: a mesh inside another without touching it is apart by the gap between the
/// surfaces; meshes that cross or touch are at 0. Where closest pairs are not unique, any.
///  - Volumes: Obb and Sphere trees. Both move whole with their pose (no refit), and a certified
///    lower bound on the distance between two of them costs a few dot products (volume_gap.h):
///    boxes fit a surface closely and the line of centres and their faces give tight gaps;
///    balls are the cheapest. A pair of nodes whose lower bound exceeds the best distance so far
///    plus its error is pruned, which never drops a closer pair; the nearer child pair is
///    visited first.
///  - Certified: the witnesses' triangles are placed in floating point (each coordinate within
///    transform_error_bound of the exact placement); distance_error covers the triangle
///    distances' errors over every pair evaluated (a pair pruned is farther than the answer),
///    and the placement, so |distance - the exact distance| <= distance_error; each witness lies
///    within point_error of its placed mesh.
///  - Domain: meshes valid (mesh_problem) and of magnitude at most 2^300, poses finite with
///    rotations as RigidTransform asks and translations of magnitude at most 2^300; outside it
///    (a NaN or infinite pose, a far translation) the answer of Separation::outside_the_domain. A mesh without triangles: distance +infinity, NaN
///    points, no faces, errors 0.
///  - Leaves of several triangles (BuildOptions::leaf_size) test each pair of theirs.
template <class BV>
MeshSeparation distance(const Bvh<BV>& a, const RigidTransform& pose_a, const Bvh<BV>& b, const RigidTransform& pose_b);

/// The same answer's definition without a hierarchy: every triangle of a against every
/// triangle of b, placed the same way, the nearest pair kept (on a tie the first in a's then
/// b's face order). Its distance is distance()'s within their errors.
MeshSeparation distance_brute_force(const Mesh& a, const RigidTransform& pose_a, const Mesh& b,
                                    const RigidTransform& pose_b);

}  // namespace cc
