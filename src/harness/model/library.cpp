#include "harness/model/library.h"

#include "harness/model/subject.h"

namespace cc::harness {

Answer ask_library(const Input& input) {
  if (const Subject* subject = subject_under_test()) return subject->ask(input);
  return std::visit([]<class In>(const In& in) { return Query<In>::ask(in); }, input);
}

std::vector<Opinion> library_alternatives(const Input& input) {
  if (subject_under_test() != nullptr) return {};  // a subject's own ways are its business
  return std::visit(
      []<class In>(const In& in) -> std::vector<Opinion> {
        if constexpr (requires { Query<In>::library_parties(); }) {
          return ask_parties(Query<In>::library_parties(), in);
        } else {
          return {};
        }
      },
      input);
}

}  // namespace cc::harness
