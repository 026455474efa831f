#include "harness/judging/evaluate.h"

#include <string>
#include <system_error>

#include "harness/formats/case_file.h"
#include "harness/model/library.h"
#include "harness/processes/child.h"

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

void restore_bands(std::vector<Opinion>& opinions, const SecondOpinion& second, QueryKind kind) {
  const std::vector<PartyBand> declared = second.parties(kind);
  for (Opinion& o : opinions) {
    for (const PartyBand& p : declared) {
      if (p.party == o.party) o.band = p.band;
    }
  }
}

std::optional<Evaluation> evaluate_in_child(const Input& input, const ExactReference& exact, const SecondOpinion& second) {
  ChildEnd child;
  try {
    child = run_in_child([&](int out) {
      return write_all(out, opinions_to_json(evaluate(input, exact, &second).opinions).dump()) ? 0 : 1;
    });
  } catch (const std::system_error&) {
    return std::nullopt;
  }
  if (!child.succeeded()) return std::nullopt;
  const std::string& text = child.output;
  Evaluation e;
  try {
    e.opinions = opinions_from_json(Json::parse(text), "");
    restore_bands(e.opinions, second, kind_of(input));
  } catch (const std::exception&) {
    return std::nullopt;
  }
  e.library = ask_library(input);
  e.exact = exact.judge(input);
  e.verdict = classify(kind_of(input), e.library, e.exact, e.opinions);
  return e;
}

}  // namespace cc::harness
