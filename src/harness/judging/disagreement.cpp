#include "harness/judging/disagreement.h"

#include "harness/judging/bands.h"
#include "harness/model/kind_pieces.h"

namespace cc::harness {

std::string_view to_string(Disagreement d) {
  switch (d) {
#define CC_DISAGREEMENT_NAME(name, ...) \
  case Disagreement::name: return #name;
    CC_FOR_EACH_DISAGREEMENT(CC_DISAGREEMENT_NAME)
#undef CC_DISAGREEMENT_NAME
  }
  return "?";
}

namespace {

// What a party that is wrong got wrong, from what it said against the exact answer.
Disagreement wrong_in(Judged judged, const Answer& said, const ExactVerdict& exact) {
  if (said.hit != exact.answer.hit) {
    if (said.hit) return Disagreement::false_hit;
    return exact.margin == 0 ? Disagreement::missed_touch : Disagreement::missed_hit;
  }
  switch (judged) {
    case Judged::all_pairs:
    case Judged::first_pair:
    case Judged::frames: return Disagreement::wrong_pairs;
    case Judged::corners: return Disagreement::wrong_corners;
    case Judged::distance: return Disagreement::wrong_distance;
    case Judged::hit: break;
  }
  return Disagreement::wrong_first_hit;
}

}  // namespace

std::optional<Disagreeing> disagreement_of(QueryKind kind, const Evaluation& e) {
  const bool library_only = e.verdict.cls == CaseClass::impl_bug;
  for (std::size_t i = 0; i < e.verdict.parties.size(); ++i) {
    const PartyStanding& p = e.verdict.parties[i];
    if (p.standing != Standing::wrong && p.standing != Standing::failed) continue;
    if (library_only && i != 0 && !is_library_party(p.party)) continue;
    if (p.standing == Standing::failed) return Disagreeing{p.party, Disagreement::failed};
    const Answer& said = i == 0 ? e.library : e.opinions.at(i - 1).answer;
    return Disagreeing{p.party, wrong_in(pieces_of(kind).judged, said, e.exact)};
  }
  return std::nullopt;
}

std::string group_name(QueryKind kind, Disagreement d) {
  return std::string(name(kind)) + "." + std::string(to_string(d));
}

std::string group_of(QueryKind kind, const Evaluation& e) {
  const auto d = disagreement_of(kind, e);
  return d ? group_name(kind, d->what) : "-";
}

}  // namespace cc::harness
