#include "oracle/exact/exact_reference.h"

#include "oracle/exact/judges.h"

namespace cc::exact {

harness::ExactVerdict ExactRationalReference::judge(const harness::Input& input) const {
  return std::visit([](const auto& in) { return exact::judge(in); }, input);
}

}  // namespace cc::exact
