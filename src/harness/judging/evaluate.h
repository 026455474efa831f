// One case, answered by the three parties and classified.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "harness/judging/classify.h"
#include "harness/formats/input_json.h"
#include "harness/model/oracle.h"

namespace cc::harness {

struct Evaluation {
  Answer library;
  std::string library_failure;  // the library crashed or hung (what and where): `library` is no answer
  ExactVerdict exact;
  std::vector<Opinion> opinions;
  Verdict verdict;
};

/// The library's answer into e, or its failure when it gives none (a subject's failure, what
/// SubjectFailure says; any other exception, "threw: " and its message).
void ask_library_into(Evaluation& e, const Input& input);

/// The verdict into e once every party is heard: a library that failed is an impl_bug.
void judge_into(Evaluation& e, const Input& input);

/// Asks the library, the exact reference and (when given) the second opinions, and classifies.
Evaluation evaluate(const Input& input, const ExactReference& exact, const SecondOpinion* second);

/// The party a case's process died in (crashed, exited, or was killed at its time limit).
enum class DiedIn { library, exact, second_opinions };

/// "the library", "the exact reference", "the second opinions (FCL/libccd, Bullet, ODE)".
std::string_view died_in_name(DiedIn where);

/// How a death reads in a case: `how` (ChildEnd::what()) "in" the party.
std::string death_text(const std::string& how, DiedIn where);

/// What is known of a case whose process died in `where` (`how`: ChildEnd::what(), e.g.
/// "killed by signal 11 (Segmentation fault)"), rebuilt here without the party that died, the
/// same in the campaign and in every command, so that a case stored by one replays unchanged in
/// another. Each failure reads `how` "in" the party. Nothing is invented for a party that was
/// not asked, and only parties that returned on the input are asked here. In the library: its
/// failure, the exact verdict not computed, no opinion: an impl_bug. In the exact reference:
/// the library's answer, no verdict: undecided. In the second opinions: the library's answer,
/// the exact verdict, each second-opinion party failed (timed out when `how` is a time-out),
/// judged: an oracle_crash unless the library is wrong.
Evaluation evaluation_after_death(const Input& input, const ExactReference& exact, const SecondOpinion& second,
                                  DiedIn where, const std::string& how);

/// What the parties other than the exact reference said (the library's answer or failure, the
/// opinions), as a child process or a campaign's worker passes them back: exactly, as case
/// files store them.
Json answers_to_json(const Evaluation& e);
/// Reads them back into e, the opinions' bands restored from `second`; throws FormatError (or
/// a JSON exception) for text that is not such a record.
void answers_from_json(const Json& j, const SecondOpinion& second, QueryKind kind, Evaluation& e);

/// Opinions read back as text (from a child process, a worker) carry no band: gives each
/// second-opinion party its band as `second` declares it for the kind (a party it does not
/// declare keeps none, which classify refuses).
void restore_bands(std::vector<Opinion>& opinions, const SecondOpinion& second, QueryKind kind);

}  // namespace cc::harness
