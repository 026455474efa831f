// The query kinds. Every list of kinds in the project derives from this one: the QueryKind
// enumeration and its names, the Input variant, the dispatch to each kind's pieces, the fuzz
// targets (fuzz/CMakeLists.txt reads the list below). A kind is one line here, its input, and
// one unit in each layer that answers it:
//   src/harness/model/inputs/<kind>.h  its input and fields (included below)
//   src/harness/kinds/<kind>.h, .cpp   the library's call and band, its generator and touching
//                                      construction, features, configurations, error-bound
//                                      terms, metamorphic relations (Query<In>, kinds/query.h)
//   oracle/exact/kinds/<kind>.cpp      its exact judge and explanation
//   oracle/fcl/kinds/<kind>.cpp        its second opinions: each party's name, band and call
// Code below the kinds reaches a kind's pieces through model/kind_pieces.h, whose table
// kinds/pieces.cpp fills from every unit. A piece missing from a unit fails the build (the
// harness's pieces at compile time; the oracles' when linking).
#pragma once

#include "harness/model/inputs/aabb_aabb.h"
#include "harness/model/inputs/broadphase.h"
#include "harness/model/inputs/disc_walls.h"
#include "harness/model/inputs/kdop_kdop.h"
#include "harness/model/inputs/mesh_mesh.h"
#include "harness/model/inputs/mesh_mesh_distance.h"
#include "harness/model/inputs/mesh_mesh_first.h"
#include "harness/model/inputs/moving_obb.h"
#include "harness/model/inputs/obb_obb.h"
#include "harness/model/inputs/obb_obb_distance.h"
#include "harness/model/inputs/ray_aabb.h"
#include "harness/model/inputs/ray_mesh.h"
#include "harness/model/inputs/sphere_obb_distance.h"
#include "harness/model/inputs/sphere_sphere.h"
#include "harness/model/inputs/sphere_sphere_distance.h"
#include "harness/model/inputs/tri_aabb.h"
#include "harness/model/inputs/tri_obb.h"
#include "harness/model/inputs/tri_obb_distance.h"
#include "harness/model/inputs/tri_tri.h"
#include "harness/model/inputs/tri_tri_distance.h"
#include "harness/model/inputs/tri_tri_intersection.h"

/// X(name, Name) for every kind, one per line, in the order of QueryKind (which numbers the
/// kinds in fuzz records: a new kind goes at the end). `name` is the kind's name in case files,
/// on the command line and under corpora/; Name##Input is its input type.
#define CC_FOR_EACH_QUERY_KIND(X)                 \
  X(ray_aabb, RayAabb)                            \
  X(sphere_sphere, SphereSphere)                  \
  X(aabb_aabb, AabbAabb)                          \
  X(kdop_kdop, KdopKdop)                          \
  X(obb_obb, ObbObb)                              \
  X(tri_aabb, TriAabb)                            \
  X(tri_obb, TriObb)                              \
  X(tri_tri, TriTri)                              \
  X(mesh_mesh, MeshMesh)                          \
  X(mesh_mesh_first, MeshMeshFirst)               \
  X(broadphase, Broadphase)                       \
  X(ray_mesh, RayMesh)                            \
  X(moving_obb, MovingObb)                        \
  X(disc_walls, DiscWalls)                        \
  X(tri_tri_intersection, TriTriIntersection)     \
  X(tri_tri_distance, TriTriDistance)             \
  X(sphere_sphere_distance, SphereSphereDistance) \
  X(sphere_obb_distance, SphereObbDistance)       \
  X(mesh_mesh_distance, MeshMeshDistance)         \
  X(obb_obb_distance, ObbObbDistance)             \
  X(tri_obb_distance, TriObbDistance)
