// How many generated cases a test runs per query kind.
#pragma once

#include "harness/generation/generate.h"

namespace cc::test {

/// The cases for `kind`: `primitive_cases` for a primitive query (a few microseconds each), or
/// `hierarchy_cases` for a mesh query or a ray against a mesh, which builds hierarchies and
/// judges its near pairs exactly (about 30 ms each).
inline int case_budget(harness::QueryKind kind, int primitive_cases, int hierarchy_cases) {
  return harness::builds_hierarchies(kind) ? hierarchy_cases : primitive_cases;
}

/// The same with a fifth as many cases for the queries that build hierarchies.
inline int case_budget(harness::QueryKind kind, int primitive_cases) {
  return case_budget(kind, primitive_cases, primitive_cases / 5);
}

}  // namespace cc::test
