#include "harness/judging/evaluate.h"

#include <stdexcept>
#include <string>
#include <system_error>

#include "harness/formats/case_file.h"
#include "harness/model/library.h"
#include "harness/model/subject.h"
#include "harness/processes/child.h"

namespace cc::harness {

void ask_library_into(Evaluation& e, const Input& input) {
  try {
    e.library = ask_library(input);
  } catch (const SubjectFailure& ex) {
    e.library_failure = ex.what();
  } catch (const std::exception& ex) {
    e.library_failure = std::string("threw: ") + ex.what();
  }
}

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

Json answers_to_json(const Evaluation& e) {
  return {{"library", e.library_failure.empty() ? answer_json(e.library) : Json{{"failed", e.library_failure}}},
          {"opinions", opinions_to_json(e.opinions)}};
}

void answers_from_json(const Json& j, const SecondOpinion& second, QueryKind kind, Evaluation& e) {
  if (!j.is_object() || !j.contains("library") || !j.contains("opinions")) {
    throw FormatError("", "expected {\"library\", \"opinions\"}");
  }
  const Json& library = j["library"];
  if (library.is_object() && library.contains("failed")) {
    e.library_failure = library["failed"].get<std::string>();
  } else {
    e.library = answer_from_json(library, "/library");
  }
  e.opinions = opinions_from_json(j["opinions"], "/opinions");
  restore_bands(e.opinions, second, kind);
}

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
    child = run_in_child([&](int out) { return write_all(out, answers_to_json(evaluate(input, exact, &second)).dump()) ? 0 : 1; },
                         timeout_seconds);
  } catch (const std::system_error&) {
    return std::nullopt;
  }
  if (!child.succeeded()) return std::nullopt;
  const std::string& text = child.output;
  Evaluation e;
  try {
    answers_from_json(Json::parse(text), second, kind_of(input), e);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  e.exact = exact.judge(input);
  judge_into(e, input);
  return e;
}

}  // namespace cc::harness
