// The disagreement a case shows: its kind, its class, the exact answer, and every party that is
// not plainly right with what it said. Shrinking keeps a case's signature; a campaign stores a
// few cases per signature (with a coarser key) rather than thousands of the same defect.
#pragma once

#include <string>

#include "harness/judging/evaluate.h"

namespace cc::harness {

/// E.g. "<kind> oracle_defect exact=miss fcl.Intersect::intersect_Triangle:wrong:hit".
std::string signature_of(QueryKind kind, const Evaluation& e);

/// The signature plus coarse features of the inputs (touching, parallel, degenerate) and the
/// decade of the margin: different enough to tell defects apart, coarse enough to group them.
std::string finding_key(const Input& input, const Evaluation& e);

}  // namespace cc::harness
