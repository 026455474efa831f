// The per-kind generators behind generate() (internal to the harness).
#pragma once

#include "harness/generate.h"
#include "harness/values.h"

namespace cc::harness::detail {

RayAabbInput generate_ray_aabb(ValueSource& values, const GenerateOptions& options);
SphereSphereInput generate_sphere_sphere(ValueSource& values, const GenerateOptions& options);
AabbAabbInput generate_aabb_aabb(ValueSource& values, const GenerateOptions& options);
KdopKdopInput generate_kdop_kdop(ValueSource& values, const GenerateOptions& options);
ObbObbInput generate_obb_obb(ValueSource& values, const GenerateOptions& options);
TriAabbInput generate_tri_aabb(ValueSource& values, const GenerateOptions& options);
TriObbInput generate_tri_obb(ValueSource& values, const GenerateOptions& options);
TriTriInput generate_tri_tri(ValueSource& values, const GenerateOptions& options);
MeshPair generate_meshes(ValueSource& values, const GenerateOptions& options);
BroadphaseInput generate_broadphase(ValueSource& values, const GenerateOptions& options);
RayMeshInput generate_ray_mesh(ValueSource& values, const GenerateOptions& options);
MovingObbInput generate_moving_obb(ValueSource& values, const GenerateOptions& options);
/// A hierarchy for the library: any volume, build and walk; with `few`, one of a few per volume
/// type (for FCL's big meshes, so that the campaign's workers build each once).
LibraryBvh draw_library(Choices& choices, bool few);
/// A procedural mesh of about the given size.
ProceduralMesh draw_recipe(Choices& choices, double size);


/// A box [lo, lo + extent], extents often 0; out of contract sometimes inverted.
Aabb draw_aabb(ValueSource& values, const GenerateOptions& options);
/// A point of the box's boundary: a corner, a point on an edge or on a face.
Vec3 draw_boundary_point(ValueSource& values, const Aabb& box);
/// An OBB with a rotation from draw_rotation (or, out of contract, a non-orthonormal one).
Obb draw_obb(ValueSource& values, const GenerateOptions& options);
/// A triangle: generic, or degenerate (a segment, a point).
Triangle draw_triangle(ValueSource& values);

}  // namespace cc::harness::detail
