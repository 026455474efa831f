// Where a fuzz target aborts on an impl_bug: one function of its own, never inlined, per query
// kind and class of disagreement, named by the group (harness/judging/disagreement.h):
// impl_bug_tri_tri_missed_touch, impl_bug_ray_aabb_wrong_first_hit, ... A fuzzing service that
// groups crashes by their stack (ClusterFuzzLite, OSS-Fuzz) so keeps different bugs apart, and
// the function's name is the group `crosscheck fuzz-case` prints for the input.
#pragma once

#include "harness/judging/disagreement.h"
#include "harness/model/query_kind.h"

namespace cc::fuzz {

/// Prints "impl_bug group <kind>.<disagreement>" to stderr and aborts, from the group's function.
[[noreturn]] void abort_in_group(harness::QueryKind kind, harness::Disagreement d);

}  // namespace cc::fuzz
