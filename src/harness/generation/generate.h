// Case generators, one per kind of query (in its unit, Query<In>::generate), biased toward the
// decision boundary: shapes made to touch by construction, coordinates equal or a few ULPs
// apart, parallel and degenerate configurations, and the extreme values of ValueSource.
#pragma once

#include <filesystem>

#include "harness/generation/choices.h"
#include "harness/model/input.h"
#include "harness/model/oracle.h"

namespace cc::harness {

struct GenerateOptions {
  /// Also NaN, infinities and shapes outside the library's domains (negative radii, inverted
  /// boxes, non-orthonormal axes).
  bool out_of_contract = false;
  /// Where FCL's test meshes (env.obj, rob.obj) are, for the mesh queries; without them those
  /// draw procedural meshes only.
  std::filesystem::path mesh_folder = "corpora/meshes";
  /// The exact reference, for the constructions placed at an exact margin of the decision by
  /// bisection (margin_bisection.h); without it they stay where floating point put them.
  const ExactReference* exact = nullptr;
};

Input generate(QueryKind kind, Choices& choices, const GenerateOptions& options = {});

/// Whether a case of the kind builds hierarchies (about 30 ms each: tests and commands run fewer
/// of them).
bool builds_hierarchies(QueryKind kind);

}  // namespace cc::harness
