// The exact rational reference, as the harness sees it.
#pragma once

#include "harness/model/oracle.h"

namespace cc::exact {

class ExactRationalReference final : public harness::ExactReference {
 public:
  harness::ExactVerdict judge(const harness::Input& input) const override;
  harness::Explanation explain(const harness::Input& input) const override;
  std::vector<harness::TermError> bound_errors(const bounds::Records& records) const override;
};

}  // namespace cc::exact
