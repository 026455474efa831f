#include "harness/judging/evaluate.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "harness/formats/case_file.h"
#include "harness/model/library.h"
#include "harness/model/subject.h"

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

std::string_view died_in_name(DiedIn where) {
  switch (where) {
    case DiedIn::library: return "the library";
    case DiedIn::exact: return "the exact reference";
    case DiedIn::second_opinions: return "the second opinions (FCL/libccd, Bullet, ODE)";
  }
  return "?";
}

std::string death_text(const std::string& how, DiedIn where) {
  return how + " in " + std::string(died_in_name(where));
}

Evaluation evaluation_after_death(const Input& input, const ExactReference& exact, const SecondOpinion& second,
                                  DiedIn where, const std::string& how) {
  const std::string failure = death_text(how, where);
  Evaluation e;
  if (where == DiedIn::library) {
    e.library_failure = failure;
  } else {
    ask_library_into(e, input);
  }
  if (where != DiedIn::second_opinions) {  // nothing is invented for a party that was not asked
    e.exact.decided = false;
    e.exact.margin = NAN;
    const bool library = where == DiedIn::library;
    e.exact.note = library ? "not computed: " + failure : failure;
    e.verdict.cls = library ? CaseClass::impl_bug : CaseClass::undecided;
    e.verdict.parties = {{"library", library ? Standing::failed : Standing::not_applicable, failure}};
    return e;
  }
  e.exact = exact.judge(input);
  for (const PartyBand& party : second.parties(kind_of(input))) {
    Opinion o;
    o.party = party.party;
    o.status = is_time_out(how) ? Opinion::Status::timed_out : Opinion::Status::failed;
    o.detail = failure;
    o.band = party.band;
    e.opinions.push_back(std::move(o));
  }
  judge_into(e, input);
  if (e.verdict.cls != CaseClass::impl_bug) e.verdict.cls = CaseClass::oracle_crash;
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

}  // namespace cc::harness
