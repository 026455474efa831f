// The inputs of one query of each kind. The variant's alternatives follow QueryKind's order.
#pragma once

#include <optional>
#include <variant>
#include <vector>

#include "collide/aabb.h"
#include "collide/moving_box.h"
#include "collide/obb.h"
#include "collide/ray_aabb.h"
#include "collide/sphere.h"
#include "collide/triangle.h"
#include "harness/model/mesh_query.h"
#include "harness/model/query_kind.h"

namespace cc::harness {

struct RayAabbInput {
  Ray ray;
  Aabb box;
  friend bool operator==(const RayAabbInput&, const RayAabbInput&) = default;
};
struct SphereSphereInput {
  Sphere a, b;
  friend bool operator==(const SphereSphereInput&, const SphereSphereInput&) = default;
};
struct AabbAabbInput {
  Aabb a, b;
  friend bool operator==(const AabbAabbInput&, const AabbAabbInput&) = default;
};
/// Two point sets, each fitted with a k-DOP; k is one of 6, 14, 16, 18, 24, 26.
struct KdopKdopInput {
  int k = 18;
  std::vector<Vec3> a, b;
  friend bool operator==(const KdopKdopInput&, const KdopKdopInput&) = default;
};
struct ObbObbInput {
  Obb a, b;
  friend bool operator==(const ObbObbInput&, const ObbObbInput&) = default;
};
struct TriAabbInput {
  Triangle tri;
  Aabb box;
  friend bool operator==(const TriAabbInput&, const TriAabbInput&) = default;
};
struct TriObbInput {
  Triangle tri;
  Obb box;
  friend bool operator==(const TriObbInput&, const TriObbInput&) = default;
};
struct TriTriInput {
  Triangle a, b;
  friend bool operator==(const TriTriInput&, const TriTriInput&) = default;
};

/// All colliding triangle pairs of two placed meshes.
struct MeshMeshInput {
  MeshPair meshes;
  friend bool operator==(const MeshMeshInput&, const MeshMeshInput&) = default;
};
/// Whether two placed meshes collide, and one colliding pair if they do.
struct MeshMeshFirstInput {
  MeshPair meshes;
  friend bool operator==(const MeshMeshFirstInput&, const MeshMeshFirstInput&) = default;
};

/// A set of boxes over a sequence of frames: frames[f][i] is box i in frame f, or nothing when
/// box i is not in the scene then (not yet added, or removed). Every frame has the same number
/// of slots. The answer: the overlapping pairs (i, j), i < j, of each frame.
struct BroadphaseInput {
  std::vector<std::vector<std::optional<Aabb>>> frames;
  friend bool operator==(const BroadphaseInput&, const BroadphaseInput&) = default;
};
/// The first point where a ray meets a mesh (its own frame), through the library's hierarchy.
struct RayMeshInput {
  MeshRef mesh;
  Ray ray;
  LibraryBvh library;
  friend bool operator==(const RayMeshInput&, const RayMeshInput&) = default;
};
/// Two boxes moving with constant velocities over a step: whether they meet, and when first
/// and last.
struct MovingObbInput {
  MovingObb a, b;
  friend bool operator==(const MovingObbInput&, const MovingObbInput&) = default;
};

using Input = std::variant<RayAabbInput, SphereSphereInput, AabbAabbInput, KdopKdopInput, ObbObbInput, TriAabbInput,
                           TriObbInput, TriTriInput, MeshMeshInput, MeshMeshFirstInput, BroadphaseInput, RayMeshInput,
                           MovingObbInput>;

/// The two meshes of a mesh query; nothing for other kinds.
inline const MeshPair* meshes_of(const Input& input) {
  if (const auto* in = std::get_if<MeshMeshInput>(&input)) return &in->meshes;
  if (const auto* in = std::get_if<MeshMeshFirstInput>(&input)) return &in->meshes;
  return nullptr;
}

inline QueryKind kind_of(const Input& input) { return static_cast<QueryKind>(input.index()); }

}  // namespace cc::harness
