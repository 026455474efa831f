#include "harness/model/case_class.h"

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
    case CaseClass::exact_defect: return "exact_defect";
  }
  return "?";
}

std::optional<CaseClass> case_class_named(std::string_view name) {
  for (CaseClass c : kAllClasses) {
    if (to_string(c) == name) return c;
  }
  return std::nullopt;
}

}  // namespace cc::harness
