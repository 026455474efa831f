#include "harness/model/library.h"

#include "harness/model/kind_pieces.h"
#include "harness/model/subject.h"

namespace cc::harness {

Answer ask_library(const Input& input) {
  if (const Subject* subject = subject_under_test()) return subject->ask(input);
  return pieces_of(kind_of(input)).ask(input);
}

std::vector<Opinion> library_alternatives(const Input& input) {
  if (subject_under_test() != nullptr) return {};  // a subject's own ways are its business
  return pieces_of(kind_of(input)).library_alternatives(input);
}

}  // namespace cc::harness
