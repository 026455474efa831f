#include "harness/evaluate.h"

#include "harness/library.h"

namespace cc::harness {

Evaluation evaluate(const Input& input, const ExactReference& exact, const SecondOpinion* second) {
  Evaluation e;
  e.library = ask_library(input);
  e.exact = exact.judge(input);
  e.opinions = library_alternatives(input);
  if (second != nullptr) {
    for (Opinion& o : second->opinions(input)) e.opinions.push_back(std::move(o));
  }
  e.verdict = classify(kind_of(input), e.library, e.exact, e.opinions);
  return e;
}

}  // namespace cc::harness
