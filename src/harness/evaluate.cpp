#include "harness/evaluate.h"

#include "harness/library.h"

namespace cc::harness {

Evaluation evaluate(const Input& input, const ExactReference& exact, const SecondOpinion* second) {
  Evaluation e;
  e.library = ask_library(input);
  e.exact = exact.judge(input);
  if (second != nullptr) e.opinions = second->opinions(input);
  e.verdict = classify(kind_of(input), e.library, e.exact, e.opinions);
  return e;
}

}  // namespace cc::harness
