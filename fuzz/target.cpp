// One fuzz target; CMake builds it once per query kind with CROSSCHECK_FUZZ_QUERY set to the
// kind's name (fuzz_ray_aabb, fuzz_obb_obb, ...).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_target.h"

namespace {
constexpr auto kKind = cc::harness::QueryKind::CROSSCHECK_FUZZ_QUERY;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return cc::fuzz::test_one_input(kKind, data, size);
}

#ifdef CROSSCHECK_CUSTOM_MUTATOR
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  return cc::fuzz::mutate(kKind, data, size, max_size, seed);
}
#endif
