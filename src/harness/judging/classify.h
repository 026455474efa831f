// How a case is classified from the three answers.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "harness/model/answer.h"
#include "harness/model/case_class.h"
#include "harness/model/input.h"
#include "harness/model/kind_pieces.h"
#include "harness/model/oracle.h"

namespace cc::harness {

/// How one party fared against the exact answer. differs: out of contract with no exact verdict,
/// a second opinion that answers otherwise than the library documents (reported, not judged).
enum class Standing { right, within_band, wrong, not_applicable, failed, differs };
std::string_view to_string(Standing s);

struct PartyStanding {
  std::string party;  // "library" or a second opinion's name
  Standing standing = Standing::right;
  std::string why;    // for wrong / within_band / failed
};

struct Verdict {
  CaseClass cls = CaseClass::agree;
  std::vector<PartyStanding> parties;  // the library first
};

/// Classifies a case from the library's answer, the exact verdict and the other parties'
/// opinions (each judged by its own band; the library's parties by the kind's).
Verdict classify(QueryKind kind, const Answer& library, const ExactVerdict& exact, const std::vector<Opinion>& opinions);

/// The same for answers judged as a kind's are (`judged`, with the library's band), e.g. the
/// pairs of two placed meshes outside a case.
Verdict classify(const Band& library_band, Judged judged, const Answer& library, const ExactVerdict& exact,
                 const std::vector<Opinion>& opinions);

/// How a kind's answers are judged (its unit says).
Judged judged_of(QueryKind kind);

}  // namespace cc::harness
