// One case, answered by the three parties and classified.
#pragma once

#include <vector>

#include "harness/classify.h"
#include "harness/oracle.h"

namespace cc::harness {

struct Evaluation {
  Answer library;
  ExactVerdict exact;
  std::vector<Opinion> opinions;
  Verdict verdict;
};

/// Asks the library, the exact reference and (when given) the second opinions, and classifies.
Evaluation evaluate(const Input& input, const ExactReference& exact, const SecondOpinion* second);

}  // namespace cc::harness
