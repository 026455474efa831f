#include "oracle/cgal/exact_audit.h"

#include <stdexcept>
#include <tuple>

namespace cc::cgal {
namespace {

// An input of two fields that cgal_answer takes, in the order of its fields.
template <class In>
concept TwoShapes = std::tuple_size_v<std::remove_cv_t<decltype(harness::Fields<In>::list)>> == 2 &&
                    requires(const In& in) {
                      cgal_answer(std::get<0>(harness::Fields<In>::list).of(in),
                                  std::get<1>(harness::Fields<In>::list).of(in));
                    };

int sign_of(double margin) { return (margin > 0) - (margin < 0); }

}  // namespace

bool answers(harness::QueryKind kind) {
  return harness::with_kind(kind, []<class In>() { return TwoShapes<In>; });
}

std::optional<CgalAnswer> cgal_answer(const harness::Input& input) {
  return std::visit(
      []<class In>(const In& in) -> std::optional<CgalAnswer> {
        if constexpr (TwoShapes<In>) {
          return cgal_answer(std::get<0>(harness::Fields<In>::list).of(in), std::get<1>(harness::Fields<In>::list).of(in));
        } else {
          return std::nullopt;
        }
      },
      input);
}

bool Audit::touching() const {
  return (outcome == AuditOutcome::agree || outcome == AuditOutcome::disagree) && exact.margin == 0 &&
         exact.answer.hit;
}

Audit audit_case(const harness::Input& input, const harness::ExactReference& exact) {
  Audit a;
  a.exact = exact.judge(input);
  if (a.exact.contract != harness::Contract::in) {
    a.outcome = AuditOutcome::out_of_contract;
    return a;
  }
  if (!a.exact.decided) {
    a.outcome = AuditOutcome::undecided;
    return a;
  }
  const std::optional<CgalAnswer> cgal = cgal_answer(input);
  if (!cgal) throw std::invalid_argument("audit_case: CGAL does not answer " + std::string(harness::name(harness::kind_of(input))));
  a.cgal = *cgal;
  const auto says = [](bool hit) { return hit ? "hit" : "miss"; };
  if (a.cgal.hit != a.exact.answer.hit) {
    a.why = std::string("exact reference says ") + says(a.exact.answer.hit) + ", CGAL says " + says(a.cgal.hit);
  } else if (a.cgal.margin_sign && *a.cgal.margin_sign != sign_of(a.exact.margin)) {
    a.why = "exact reference's margin " + std::to_string(a.exact.margin) + " has not the sign of CGAL's " +
            std::to_string(*a.cgal.margin_sign);
  }
  a.outcome = a.why.empty() ? AuditOutcome::agree : AuditOutcome::disagree;
  return a;
}

}  // namespace cc::cgal
