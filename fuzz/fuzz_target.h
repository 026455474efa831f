// What every fuzz target does, for the kind it is built for.
#pragma once

#include <cstddef>
#include <cstdint>

#include "harness/model/query_kind.h"

namespace cc::fuzz {

/// Decodes the record at the front of the input (harness/formats/fuzz_record.h), answers it three ways
/// and classifies it. An impl_bug prints the case and aborts from its group's function
/// (impl_bug_groups.h), so that the fuzzer keeps the input and a service tells its bugs apart.
/// An oracle_defect, or a second opinion that threw or did not return, is written to
/// $CROSSCHECK_FUZZ_FINDINGS/<query>/ (when that variable is set) and fuzzing goes on.
int test_one_input(harness::QueryKind kind, const std::uint8_t* data, std::size_t size);

/// The custom mutator: geometric boundary moves on the record's values (copy one coordinate
/// into another, step one by 1 to 4 ULPs, swap in a special value, flip a sign, move one shape
/// to touch the other by construction), or else libFuzzer's own mutation.
std::size_t mutate(harness::QueryKind kind, std::uint8_t* data, std::size_t size, std::size_t max_size,
                   unsigned int seed);

}  // namespace cc::fuzz
