// Replaying a stored case: what changed between the case as recorded and its evaluation now.
#pragma once

#include <string>
#include <vector>

#include "harness/formats/case_file.h"
#include "harness/judging/evaluate.h"

namespace cc::harness {

/// One line per change, none when the replay is the record: the library now wrong (unless the
/// case was recorded an impl_bug with the same answer or failure: a known bug, unchanged); any party's
/// whole answer (hit, parameters, pairs, frames; doubles bit for bit) or status changed, the
/// library's and the exact reference's included; the exact contract, decidedness or margin
/// changed; a recorded party gone or a party not in the record; the class changed. Whether a
/// call returns in time depends on the machine: a party that timed out in the record or now has
/// not changed, nor has the class, nor a party missing on one side then; after a time-out of the
/// library or the exact reference (which leaves the exact verdict unasked), nor has the exact
/// verdict.
std::vector<std::string> replay_changes(const Case& recorded, const Evaluation& now);

}  // namespace cc::harness
