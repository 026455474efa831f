// What a party got wrong, in a few words: the class of disagreement ("missed_touch",
// "false_hit", ...) and, with the query kind, the group it names ("<kind>.missed_touch"). The
// same group names a fuzz target's abort function (fuzz/impl_bug_groups.h), `fuzz-case`'s line,
// a campaign's finding in JSON and the report's cards, so that a crash grouped by its stack and a
// finding grouped on the page are the same group.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "harness/judging/evaluate.h"

namespace cc::harness {

/// X(name) for every class of disagreement, in the order of Disagreement.
#define CC_FOR_EACH_DISAGREEMENT(X, ...) \
  X(failed, __VA_ARGS__)                 \
  X(missed_touch, __VA_ARGS__)           \
  X(missed_hit, __VA_ARGS__)             \
  X(false_hit, __VA_ARGS__)              \
  X(wrong_first_hit, __VA_ARGS__)        \
  X(wrong_pairs, __VA_ARGS__)            \
  X(wrong_corners, __VA_ARGS__)          \
  X(wrong_distance, __VA_ARGS__)

#define CC_DISAGREEMENT_ENUMERATOR(name, ...) name,
/// failed: the party threw, crashed, hung or gave no answer. missed_touch: it says miss where the
/// shapes touch (exact margin 0); missed_hit: miss where they overlap; false_hit: hit where they
/// are apart. Where the hit agrees, what comes with it is wrong: the first hit's parameters (a
/// ray's t, a first contact time), the pairs named (two meshes, boxes over frames), the corners of
/// an intersection, or a distance or its closest points.
enum class Disagreement { CC_FOR_EACH_DISAGREEMENT(CC_DISAGREEMENT_ENUMERATOR) };
#undef CC_DISAGREEMENT_ENUMERATOR

std::string_view to_string(Disagreement d);

struct Disagreeing {
  std::string party;  // "library", "library.<way>" or a second opinion's name
  Disagreement what;
};

/// The disagreement that makes the case's class: of the first of the library's parties that is
/// wrong or failed in an impl_bug, else of the first party wrong or failed. Nothing when no party
/// is (agree, boundary, out of contract, undecided).
std::optional<Disagreeing> disagreement_of(QueryKind kind, const Evaluation& e);

/// "<kind>.<disagreement>", the kind by its name, e.g. "<kind>.false_hit".
std::string group_name(QueryKind kind, Disagreement d);

/// The group of the case's disagreement, or "-" when it has none.
std::string group_of(QueryKind kind, const Evaluation& e);

}  // namespace cc::harness
