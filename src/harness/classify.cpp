#include "harness/classify.h"

#include <cmath>
#include <sstream>

#include "harness/bands.h"

namespace cc::harness {

std::string_view to_string(CaseClass c) {
  switch (c) {
    case CaseClass::agree: return "agree";
    case CaseClass::impl_bug: return "impl_bug";
    case CaseClass::oracle_defect: return "oracle_defect";
    case CaseClass::oracle_crash: return "oracle_crash";
    case CaseClass::boundary: return "boundary";
    case CaseClass::out_of_contract: return "out_of_contract";
    case CaseClass::undecided: return "undecided";
  }
  return "?";
}

std::optional<CaseClass> case_class_named(std::string_view name) {
  for (CaseClass c : kAllClasses) {
    if (to_string(c) == name) return c;
  }
  return std::nullopt;
}

std::string_view to_string(Standing s) {
  switch (s) {
    case Standing::right: return "right";
    case Standing::within_band: return "within band";
    case Standing::wrong: return "wrong";
    case Standing::not_applicable: return "n/a";
    case Standing::failed: return "failed";
  }
  return "?";
}

namespace {

std::string describe(bool says_hit, const ExactVerdict& exact) {
  std::ostringstream s;
  s << "says " << (says_hit ? "hit" : "miss") << ", exact " << (exact.answer.hit ? "hit" : "miss") << " at margin "
    << exact.margin;
  return s.str();
}

// Parameters (ray t) within the band's relative width of the exact ones.
bool params_agree(const Band& band, const Answer& said, const Answer& exact) {
  if (said.params.size() != exact.params.size()) return false;
  for (std::size_t i = 0; i < said.params.size(); ++i) {
    const double a = said.params[i], e = exact.params[i];
    if (a == e) continue;  // also equal infinities
    if (!(std::fabs(a - e) <= band.param_width * std::fabs(e) + 0x1p-1060)) return false;
  }
  return true;
}

PartyStanding judge_party(std::string party, const Band& band, const Answer& said, const ExactVerdict& exact) {
  PartyStanding p{std::move(party), Standing::right, ""};
  if (said.hit != exact.answer.hit) {
    p.standing = within_band(band, said.hit, exact.margin) ? Standing::within_band : Standing::wrong;
    p.why = describe(said.hit, exact);
  } else if (said.hit && band.param_width > 0 && !params_agree(band, said, exact.answer)) {
    p.standing = Standing::wrong;
    std::ostringstream s;
    s.precision(17);
    s << "parameters differ:";
    for (double v : said.params) s << ' ' << v;
    s << " vs exact";
    for (double v : exact.answer.params) s << ' ' << v;
    p.why = s.str();
  }
  return p;
}

}  // namespace

Verdict classify(QueryKind kind, const Answer& library, const ExactVerdict& exact, const std::vector<Opinion>& opinions) {
  Verdict v;
  if (exact.contract != Contract::in) {
    PartyStanding lib{"library", Standing::right, exact.note};
    if (exact.contract == Contract::documented && library.hit != exact.answer.hit) {
      lib.standing = Standing::wrong;
      lib.why = "breaks its documented answer (" + std::string(exact.answer.hit ? "hit" : "miss") + ") for: " + exact.note;
    }
    v.parties.push_back(lib);
    v.cls = lib.standing == Standing::wrong ? CaseClass::impl_bug : CaseClass::out_of_contract;
    return v;
  }
  if (!exact.decided) {
    v.parties.push_back({"library", Standing::not_applicable, exact.note});
    v.cls = CaseClass::undecided;
    return v;
  }

  v.parties.push_back(judge_party("library", library_band(kind), library, exact));
  bool any_wrong = false, any_failed = false, any_band = v.parties[0].standing == Standing::within_band;
  for (const Opinion& o : opinions) {
    if (o.status == Opinion::Status::not_applicable) {
      v.parties.push_back({o.party, Standing::not_applicable, o.detail});
      continue;
    }
    if (o.status == Opinion::Status::failed) {
      v.parties.push_back({o.party, Standing::failed, o.detail});
      any_failed = true;
      continue;
    }
    Band band = party_band(o.party);
    band.param_width = 0;  // second opinions give no parameters
    v.parties.push_back(judge_party(o.party, band, o.answer, exact));
    any_wrong |= v.parties.back().standing == Standing::wrong;
    any_band |= v.parties.back().standing == Standing::within_band;
  }
  if (v.parties[0].standing == Standing::wrong) {
    v.cls = CaseClass::impl_bug;
  } else if (any_failed) {
    v.cls = CaseClass::oracle_crash;
  } else if (any_wrong) {
    v.cls = CaseClass::oracle_defect;
  } else if (any_band) {
    v.cls = CaseClass::boundary;
  } else {
    v.cls = CaseClass::agree;
  }
  return v;
}

}  // namespace cc::harness
