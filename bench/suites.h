// The benchmark suites of the bench binary, one per concept, registered before the run.
#pragma once

namespace cc::bench {

/// aabb_aabb, sphere_sphere, kdop_kdop (overlap and fitting), obb_obb, tri_obb, tri_tri:
/// library and FCL on the same pairs (primitives_bench.cpp).
void register_primitive_benchmarks();
/// ray_aabb, scalar and batched, library only (ray_aabb_bench.cpp).
void register_ray_benchmarks();
/// Hierarchies: build time, bytes per triangle, env.obj against rob.obj all pairs
/// (hierarchy_bench.cpp).
void register_hierarchy_benchmarks();
/// Broadphase: coherent boxes per frame, 1k, 10k, 100k (broadphase_bench.cpp).
void register_broadphase_benchmarks();

}  // namespace cc::bench
