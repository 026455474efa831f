#include "harness/model/library.h"

namespace cc::harness {

Answer ask_library(const Input& input) {
  return std::visit([]<class In>(const In& in) { return Query<In>::ask(in); }, input);
}

std::vector<Opinion> library_alternatives(const Input& input) {
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
