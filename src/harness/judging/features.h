// What kind of configuration a case is, for the properties' statistics: each property counts
// how often it met touching, parallel and degenerate configurations, and fails if it never
// met one of those that apply to its query. Parallel and degenerate are each kind's to say (its
// unit's features()); touching is the exact verdict's.
#pragma once

#include "harness/judging/shape_facts.h"
#include "harness/model/input.h"
#include "harness/model/kind_pieces.h"
#include "harness/model/oracle.h"

namespace cc::harness {

/// The features of a case, given the exact verdict on it.
Features features_of(const Input& input, const ExactVerdict& exact);

/// Whether "parallel" means something for this kind (a direction component of 0, equal face
/// coordinates, a common slab plane, parallel edges or faces); spheres have no such
/// configuration. The kind's unit says.
bool parallel_applies(QueryKind kind);

/// Two oriented boxes: parallel axes; a zero half extent.
Features obb_pair_features(const Obb& a, const Obb& b);

}  // namespace cc::harness
