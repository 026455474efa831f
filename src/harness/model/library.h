// The library's answer to a query, and its other ways to answer it: each kind's unit says
// (Query<In>::ask, library_parties).
#pragma once

#include <vector>

#include "harness/model/answer.h"
#include "harness/model/input.h"

namespace cc::harness {

/// The answer of the library under test: crosscheck's own, or the subject put under test
/// (subject.h).
Answer ask_library(const Input& input);

/// The library's other ways to answer the same query, each a party named "library.<how>" with
/// the kind's band, judged like the library itself (an exception is a failed opinion, and a
/// wrong or failed one is an impl_bug); nothing for kinds that have none, or with a subject under
/// test.
std::vector<Opinion> library_alternatives(const Input& input);

}  // namespace cc::harness
