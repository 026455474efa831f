#include "oracle/exact/exact_reference.h"

#include "oracle/exact/judges.h"

namespace cc::exact {

harness::ExactVerdict ExactRationalReference::judge(const harness::Input& input) const {
  return std::visit([]<class In>(const In& in) { return exact::judge<In>(in); }, input);
}

harness::Explanation ExactRationalReference::explain(const harness::Input& input) const {
  const harness::ExactVerdict v = judge(input);
  if (v.contract != harness::Contract::in) {
    harness::Explanation e;
    e.title = "outside the library's domain";
    e.facts = {{"contract", v.contract == harness::Contract::documented ? "documented answer" : "unspecified answer"},
               {"why", v.note}};
    e.deciding = v.note;
    return e;
  }
  return std::visit([]<class In>(const In& in) { return exact::explain<In>(in); }, input);
}

}  // namespace cc::exact
