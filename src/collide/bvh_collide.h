// Two hierarchies against each other under rigid motion: the first colliding triangle pair
// (collision detection) or all of them (collision determination).
#pragma once

#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "collide/bvh.h"
#include "collide/bvh_lazy.h"
#include "collide/rigid_transform.h"

namespace cc {

enum class CollisionMode { first_hit, all_pairs };

/// How an Aabb or k-DOP of b is brought into a's frame when b moves relative to a (an OBB or a
/// sphere is moved with the relative transform itself and needs no update). Both results are padded to
/// cover the rounding of the transform, so they contain b's moved triangles as the leaf test
/// sees them.
enum class BvUpdate {
  approximate,  // refit around the moved original volume (Klosowski et al.; see moved_volume)
  exact,        // refit around the moved vertices of the convex hull of the node's triangles
  /// The exact update's volume, found by hill climbing (Klosowski et al.): per slab direction,
  /// a walk over the node's hull graph (BuildOptions::hull_graphs) from where the last walk
  /// ended to the hull point highest along it, certified exact (see moved_volume); a node
  /// without a graph, or a walk not certified, takes the exact update.
  hill_climbing,
};

/// Which hierarchy to descend when both nodes are internal.
enum class Descent {
  first_model,  // always a's, as in the pseudocode of the lecture notes (FindFirstHitCD)
  larger,       // the one whose volume is larger (ties: a's)
};

std::string_view to_string(CollisionMode m);
std::string_view to_string(BvUpdate u);
std::string_view to_string(Descent d);

struct CollideOptions {
  CollisionMode mode = CollisionMode::all_pairs;
  BvUpdate update = BvUpdate::approximate;
  Descent descent = Descent::first_model;
  friend bool operator==(const CollideOptions&, const CollideOptions&) = default;
};

/// What a query cost, for the cost function T = n_v c_v + n_p c_p + n_u c_u.
struct CollisionCounters {
  std::uint64_t bv_tests = 0;         // n_v: volume-volume overlap tests
  std::uint64_t primitive_tests = 0;  // n_p: triangle-triangle tests
  std::uint64_t bv_updates = 0;       // n_u: volumes of b brought into a's frame
  std::uint64_t update_points = 0;    // points the updates evaluated: moved (exact) or walked over (hill climbing)
  std::uint64_t climbed = 0;          // hill climbing: updates whose walks were all certified
  friend bool operator==(const CollisionCounters&, const CollisionCounters&) = default;
};

struct CollisionResult {
  /// Colliding pairs (face of a's mesh, face of b's mesh), sorted. first_hit: at most one, the
  /// first found in the traversal order.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  CollisionCounters counters;
};

/// The triangle pairs of a (placed by pose_a) and b (placed by pose_b) that share a point, by
/// test_triangle_triangle on a's triangles and b's triangles moved into a's frame by
/// relative(pose_a, pose_b) (each vertex by apply()).
///  - The hierarchies only prune: every volume test is conservative for the triangles as the
///    leaf test sees them, so a pair that shares a point is never lost. The pairs are those of
///    collide_brute_force, whatever the volume type, build and options, except possibly pairs
///    apart by less than the leaf test's tolerance, which it may report while a volume test
///    prunes them.
///  - Surfaces only: a mesh inside another without touching it gives no pair.
///  - Poses: finite rotations (see RigidTransform); meshes valid (mesh_problem) and of
///    magnitude at most 2^300.
template <class BV>
CollisionResult collide(const Bvh<BV>& a, const RigidTransform& pose_a, const Bvh<BV>& b, const RigidTransform& pose_b,
                        const CollideOptions& options);

/// The same on lazy hierarchies (bvh_lazy.h), splitting their nodes as the walk descends into
/// them; the answer is collide()'s on the eager top-down trees for Aabb and k-DOP trees, and
/// differs at most by pairs within the leaf test's band for Obb and sphere trees. a and b must
/// be different trees (a mesh against itself: two LazyBvh).
template <class BV>
CollisionResult collide(LazyBvh<BV>& a, const RigidTransform& pose_a, LazyBvh<BV>& b, const RigidTransform& pose_b,
                        const CollideOptions& options);

/// The volume of b's node in a's frame as collide() tests it, for b moved by t (relative to a):
///  - Obb: moved by t.
///  - Sphere: its centre moved by t, its radius times a bound on how much t's rotation can
///    stretch a length (1 for an orthonormal rotation, up to rounding).
///  - Aabb and k-DOP, approximate: each slab bounds the moved original volume, through three of
///    its slabs per direction (kdop_cone): for an Aabb the box around its moved corners; for a
///    k-DOP the k-DOP around its moved polytope when its slabs meet at vertices as the cones
///    assume, a little larger otherwise. No corners are stored or computed.
///  - Aabb and k-DOP, exact: re-fitted around the node's moved hull points, if the tree has them
///    (BuildOptions::hull_points), else around all the node's moved vertices (the same volume
///    up to rounding, at the cost of every vertex).
///  - Aabb and k-DOP, hill_climbing: the exact update's volume (equal slab for slab), re-fitted
///    around fewer of the moved hull points. For each slab direction n and side, a walk climbs
///    the node's hull graph by m . p (m = R^T n rounded) to a point v no neighbour of which is
///    higher, and gathers the plateau around v: the points connected to it whose values are
///    within 2 e of v's, e being twice the rounding of m . p plus twice 2^-44 (M + 3 |T|_max)
///    |n|_1, a bound on |slab value - (m . p + n . T)| over the hull points. Every hull point off
///    the plateau is then lower than v in exact arithmetic by more than the latter (a climbing
///    path from it would enter the plateau through a point next to it), so the plateau's points
///    give the slab. A node without a graph (small nodes have none: BuildOptions::hull_graphs),
///    or a plateau of more than 64 points: the exact update.
/// Padded by 2^-43 of b's magnitude plus |t's translation| (times the 1-norm of a k-DOP's slab
/// direction), so that it contains, in exact arithmetic, the node's triangles moved as the leaf
/// test sees them (each vertex by apply(t, v)).
template <class BV>
BV moved_volume(const Bvh<BV>& b, std::size_t node, const RigidTransform& t, BvUpdate update);

/// All pairs without a hierarchy: every triangle of a against every triangle of b, moved the
/// same way as collide() moves them. Its pairs are collide()'s, for any hierarchy.
std::vector<std::pair<std::uint32_t, std::uint32_t>> collide_brute_force(const Mesh& a, const RigidTransform& pose_a,
                                                                         const Mesh& b, const RigidTransform& pose_b);

}  // namespace cc
