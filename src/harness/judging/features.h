// What kind of configuration a case is, for the properties' statistics: each property counts
// how often it met touching, parallel and degenerate configurations, and fails if it never
// met one of those that apply to its query.
#pragma once

#include "harness/model/input.h"
#include "harness/model/oracle.h"

namespace cc::harness {

struct Features {
  bool touching = false;    // in contract, and the exact margin is 0 with a hit
  bool parallel = false;    // see parallel_applies()
  bool degenerate = false;  // zero extent, zero radius, zero direction, a degenerate triangle...
};

/// The features of a case, given the exact verdict on it.
Features features_of(const Input& input, const ExactVerdict& exact);

/// Whether "parallel" means something for this kind: a direction component of 0 (ray_aabb),
/// equal face coordinates (aabb_aabb), a common slab plane (kdop_kdop), parallel edges or
/// faces (obb_obb, tri_*). Spheres have no such configuration.
bool parallel_applies(QueryKind kind);

}  // namespace cc::harness
