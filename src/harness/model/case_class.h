// The class of a case: what its answers say about the library and the other parties, as the
// judge decides it (judging/classify.h) and case files store it.
#pragma once

#include <optional>
#include <string_view>

namespace cc::harness {

enum class CaseClass {
  agree,            // every party matches the exact answer
  impl_bug,         // the library is wrong outside its band (or breaks its documented answer)
  oracle_defect,    // a second opinion is wrong outside its band, the library is right
  oracle_crash,     // a second opinion threw or crashed
  boundary,         // some party differs, inside its band
  out_of_contract,  // inputs outside the library's domain; its documented answer holds
  undecided,        // the exact reference cannot decide
  exact_defect,     // CGAL's exact kernel and the exact reference disagree (crosscheck audit-exact)
};

inline constexpr CaseClass kAllClasses[] = {CaseClass::agree,          CaseClass::impl_bug,       CaseClass::oracle_defect,
                                            CaseClass::oracle_crash,   CaseClass::boundary,       CaseClass::out_of_contract,
                                            CaseClass::undecided,      CaseClass::exact_defect};

/// Its name in case files and summaries ("impl_bug").
std::string_view to_string(CaseClass c);
/// The class of that name, or nothing.
std::optional<CaseClass> case_class_named(std::string_view name);

}  // namespace cc::harness
