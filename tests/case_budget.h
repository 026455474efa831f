// How many generated cases a test runs per query kind.
#pragma once

#include "harness/query_kind.h"

namespace cc::test {

/// The cases for `kind` out of `primitive_cases`, the count a primitive query gets (a few
/// microseconds each): a mesh case (or a ray against a mesh) builds hierarchies and judges its
/// near pairs exactly, about 30 ms, and gets a fifth as many.
inline int case_budget(harness::QueryKind kind, int primitive_cases) {
  const bool builds_hierarchies = harness::is_mesh_query(kind) || kind == harness::QueryKind::ray_mesh;
  return builds_hierarchies ? primitive_cases / 5 : primitive_cases;
}

}  // namespace cc::test
