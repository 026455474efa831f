#include "harness/judging/evaluate.h"

#include <stdexcept>
#include <string>
#include <system_error>

#include "harness/formats/case_file.h"
#include "harness/model/library.h"
#include "harness/processes/child.h"

namespace cc::harness {
namespace {

// The library's answer into e, or its failure when it throws (a subject's answer that is no
// answer, subject.h).
void ask_library_into(Evaluation& e, const Input& input) {
  try {
    e.library = ask_library(input);
  } catch (const std::exception& ex) {
    e.library_failure = std::string("threw: ") + ex.what();
  }
}

// The verdict once every party is heard: a library that failed is an impl_bug.
void judge_into(Evaluation& e, const Input& input) {
  e.verdict = classify(kind_of(input), e.library, e.exact, e.opinions);
  if (e.library_failure.empty()) return;
  e.verdict.cls = CaseClass::impl_bug;
  const PartyStanding failure{"library", Standing::failed, e.library_failure};
  if (e.verdict.parties.empty()) {
    e.verdict.parties.push_back(failure);
  } else {
    e.verdict.parties.front() = failure;
  }
}

}  // namespace

Evaluation evaluate(const Input& input, const ExactReference& exact, const SecondOpinion* second) {
  Evaluation e;
  ask_library_into(e, input);
  e.exact = exact.judge(input);
  e.opinions = library_alternatives(input);
  if (second != nullptr) {
    for (Opinion& o : second->opinions(input)) e.opinions.push_back(std::move(o));
  }
  judge_into(e, input);
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

std::optional<Evaluation> evaluate_in_child(const Input& input, const ExactReference& exact, const SecondOpinion& second,
                                            double timeout_seconds) {
  ChildEnd child;
  try {
    child = run_in_child(
        [&](int out) { return write_all(out, opinions_to_json(evaluate(input, exact, &second).opinions).dump()) ? 0 : 1; },
        timeout_seconds);
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
  ask_library_into(e, input);
  e.exact = exact.judge(input);
  judge_into(e, input);
  return e;
}

}  // namespace cc::harness
