// The library's answer to a query.
#pragma once

#include "harness/answer.h"
#include "harness/input.h"

namespace cc::harness {

Answer ask_library(const Input& input);

}  // namespace cc::harness
