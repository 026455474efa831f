// The parts of the queries on meshes: a mesh and where it comes from, the hierarchy the library is
// asked to use, two meshes placed by their poses.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "collide/bvh_collide.h"
#include "collide/mesh.h"
#include "collide/rigid_transform.h"
#include "collide/procedural_mesh.h"

namespace cc::harness {

/// A mesh and where it comes from, as a case file names it: an OBJ file (by the path the case
/// gives, see mesh_files.h), a recipe, or its triangles written out. Copies share the mesh.
struct MeshRef {
  enum class Source { file, procedural, triangles };
  Source source = Source::triangles;
  std::string file;          // file: the path as written in the case
  ProceduralMesh recipe;     // procedural
  std::shared_ptr<const Mesh> mesh;

  friend bool operator==(const MeshRef& a, const MeshRef& b);
};

/// A mesh given by its triangles.
MeshRef triangles_mesh(Mesh mesh);
/// The mesh of a recipe.
MeshRef procedural_mesh(const ProceduralMesh& recipe);

/// The bounding-volume types the library's hierarchies take.
enum class BvType { aabb, obb, kdop6, kdop14, kdop16, kdop18, kdop24, kdop26, sphere };
inline constexpr BvType kAllBvTypes[] = {BvType::aabb,   BvType::obb,    BvType::kdop6,  BvType::kdop14, BvType::kdop16,
                                         BvType::kdop18, BvType::kdop24, BvType::kdop26, BvType::sphere};
/// Whether b's volumes of this type are moved whole under a rotation (OBBs, spheres), so that a
/// case's `update` (approximate or exact) does not apply.
constexpr bool moved_whole(BvType t) { return t == BvType::obb || t == BvType::sphere; }
std::string_view to_string(BvType t);
std::optional<BvType> bv_type_named(std::string_view name);

/// Calls f.template operator()<BV>() with the type named by t.
template <class F>
decltype(auto) with_bv_type(BvType t, F&& f) {
  switch (t) {
    case BvType::aabb: return f.template operator()<Aabb>();
    case BvType::obb: return f.template operator()<Obb>();
    case BvType::kdop6: return f.template operator()<Kdop<6>>();
    case BvType::kdop14: return f.template operator()<Kdop<14>>();
    case BvType::kdop16: return f.template operator()<Kdop<16>>();
    case BvType::kdop18: return f.template operator()<Kdop<18>>();
    case BvType::kdop24: return f.template operator()<Kdop<24>>();
    case BvType::kdop26: return f.template operator()<Kdop<26>>();
    case BvType::sphere: break;
  }
  return f.template operator()<Sphere>();
}

/// How the library answers a mesh query: the hierarchy it builds for both meshes and how it
/// walks them. The pairs must not depend on it (beyond the leaf test's band).
struct LibraryBvh {
  BvType bv = BvType::obb;
  BuildOptions build;
  BvUpdate update = BvUpdate::approximate;
  Descent descent = Descent::first_model;
  friend bool operator==(const LibraryBvh&, const LibraryBvh&) = default;
};

/// Mesh a placed by pose_a against mesh b placed by pose_b.
struct MeshPair {
  MeshRef a, b;
  RigidTransform pose_a, pose_b;
  LibraryBvh library;
  friend bool operator==(const MeshPair&, const MeshPair&) = default;
};

}  // namespace cc::harness
