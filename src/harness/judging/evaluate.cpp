#include "harness/judging/evaluate.h"

#include <stdexcept>
#include <string>
#include <system_error>

#include "harness/formats/case_file.h"
#include "harness/model/library.h"
#include "harness/processes/child.h"

namespace cc::harness {

Evaluation evaluate(const Input& input, const ExactReference& exact, const SecondOpinion* second) {
  Evaluation e;
  try {
    e.library = ask_library(input);
  } catch (const std::exception& ex) {  // a subject's answer that is no answer (subject.h)
    e.library_failure = std::string("threw: ") + ex.what();
  }
  e.exact = exact.judge(input);
  e.opinions = library_alternatives(input);
  if (second != nullptr) {
    for (Opinion& o : second->opinions(input)) e.opinions.push_back(std::move(o));
  }
  e.verdict = classify(kind_of(input), e.library, e.exact, e.opinions);
  if (!e.library_failure.empty()) {
    e.verdict.cls = CaseClass::impl_bug;
    const PartyStanding failure{"library", Standing::failed, e.library_failure};
    if (e.verdict.parties.empty()) {
      e.verdict.parties.push_back(failure);
    } else {
      e.verdict.parties.front() = failure;
    }
  }
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
