// One case, answered by the three parties and classified.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "harness/judging/classify.h"
#include "harness/model/oracle.h"

namespace cc::harness {

struct Evaluation {
  Answer library;
  std::string library_failure;  // the library crashed or hung (what and where): `library` is no answer
  ExactVerdict exact;
  std::vector<Opinion> opinions;
  Verdict verdict;
};

/// Asks the library, the exact reference and (when given) the second opinions, and classifies.
Evaluation evaluate(const Input& input, const ExactReference& exact, const SecondOpinion* second);

/// The same, first run whole in a child process, which passes its opinions back (as case files
/// store them, exactly); the library and the exact reference, which returned there, are asked
/// again here. A party that crashes, or is cut short by a jump out of its code (see
/// SecondOpinion::abandoned_calls), thus neither ends nor damages the caller. Nothing when the
/// child did not answer (it crashed, or ran past timeout_seconds when that is not 0).
std::optional<Evaluation> evaluate_in_child(const Input& input, const ExactReference& exact, const SecondOpinion& second,
                                            double timeout_seconds = 0);

/// Opinions read back as text (from a child process, a worker) carry no band: gives each
/// second-opinion party its band as `second` declares it for the kind (a party it does not
/// declare keeps none, which classify refuses).
void restore_bands(std::vector<Opinion>& opinions, const SecondOpinion& second, QueryKind kind);

}  // namespace cc::harness
