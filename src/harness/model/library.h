// The library's answer to a query.
#pragma once

#include "harness/model/answer.h"
#include "harness/model/input.h"

#include <vector>

namespace cc::harness {

Answer ask_library(const Input& input);

/// The library's other ways to answer the same query, each judged like the library itself
/// (see is_library_party): ray_aabb "library.test_ray_aabbs" (the batched test, every kernel
/// this processor runs, the case's box in a vector block and in the scalar tail; a kernel
/// differing from intersect_ray_aabb fails); mesh_mesh "library.collision_world(refit)" and
/// "library.collision_world(cube)" (the two-level pipeline: both meshes boxed as objects,
/// the broadphase, then collide); broadphase "library.sweep_and_prune" (SweepAndPrune, where the
/// library's answer is ColumnSweep's) and "library.sort_and_sweep" (a full sort every frame);
/// ray_mesh "library.ray_mesh_any" (any hit: the face, without t) and
/// "library.ray_mesh_brute_force"; moving_obb "library.sweep_aabb_aabb" (applicable when both
/// boxes are axis-aligned and their bounds centre -+ half are exact). Nothing for other kinds.
/// An exception becomes a failed opinion.
std::vector<Opinion> library_alternatives(const Input& input);

}  // namespace cc::harness
