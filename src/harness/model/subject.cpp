#include "harness/model/subject.h"

#include <algorithm>

namespace cc::harness {
namespace {

std::shared_ptr<const Subject>& under_test() {
  static std::shared_ptr<const Subject> subject;
  return subject;
}

}  // namespace

bool Subject::answers(QueryKind kind) const {
  const std::vector<std::string>& kinds = identity().kinds;
  return std::find(kinds.begin(), kinds.end(), name(kind)) != kinds.end();
}

void put_under_test(std::shared_ptr<const Subject> subject) { under_test() = std::move(subject); }
const Subject* subject_under_test() { return under_test().get(); }

bool library_answers(QueryKind kind) {
  const Subject* subject = subject_under_test();
  return subject == nullptr || subject->answers(kind);
}

}  // namespace cc::harness
