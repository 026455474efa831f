#include "harness/shrinking/signature.h"

#include <cmath>

#include "harness/judging/features.h"

namespace cc::harness {

std::string signature_of(QueryKind kind, const Evaluation& e) {
  std::string s = std::string(name(kind)) + " " + std::string(to_string(e.verdict.cls));
  s += e.exact.answer.hit ? " exact=hit" : " exact=miss";
  for (std::size_t i = 0; i < e.verdict.parties.size(); ++i) {
    const PartyStanding& p = e.verdict.parties[i];
    if (p.standing == Standing::right || p.standing == Standing::not_applicable) continue;
    s += " " + p.party + ":" + std::string(to_string(p.standing));
    if (p.standing == Standing::failed) continue;
    const bool said = i == 0 ? e.library.hit : e.opinions[i - 1].answer.hit;
    s += said ? ":hit" : ":miss";
  }
  return s;
}

std::string finding_key(const Input& input, const Evaluation& e) {
  const Features f = features_of(input, e.exact);
  std::string key = signature_of(kind_of(input), e);
  key += f.touching ? " touching" : "";
  key += f.parallel ? " parallel" : "";
  key += f.degenerate ? " degenerate" : "";
  if (std::isfinite(e.exact.margin) && e.exact.margin != 0) {
    key += " 1e" + std::to_string(static_cast<int>(std::floor(std::log10(std::fabs(e.exact.margin)))));
  }
  return key;
}

}  // namespace cc::harness
