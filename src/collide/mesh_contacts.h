// Collision determination for two placed meshes: where each colliding pair of triangles meets.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "collide/mesh.h"
#include "collide/rigid_transform.h"
#include "collide/triangle_intersection.h"

namespace cc {

/// A pair of triangles (face of a, face of b) and the corners of their intersection, in a's frame
/// (apply(pose_a, p) gives a corner in the world).
struct PairContact {
  std::uint32_t face_a = 0, face_b = 0;
  TriangleIntersection corners;
};

/// For each pair (as collide() gives them: face of a, face of b), the corners of a's triangle and
/// b's triangle moved into a's frame by relative(pose_a, pose_b) as collide()'s leaf test moves
/// them (each vertex by apply()), by intersect_triangles. So a pair's corners are exact in
/// topology for the triangles as moved; a pair apart by less than the leaf test's band, which
/// collide() may report, gets no corners. Faces out of range are not allowed.
std::vector<PairContact> mesh_contacts(const Mesh& a, const RigidTransform& pose_a, const Mesh& b,
                                       const RigidTransform& pose_b,
                                       std::span<const std::pair<std::uint32_t, std::uint32_t>> pairs);

}  // namespace cc
