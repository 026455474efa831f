#include "collide/simd.h"

#include <array>
#include <atomic>
#include <stdexcept>
#include <string>

namespace cc::simd {
namespace {

constexpr std::size_t index_of(Kernel k) { return static_cast<std::size_t>(k); }

// -1: none forced; else the index of the forced kernel.
std::atomic<int> g_forced{-1};

// Whether this build has the vector kernels. Each is compiled for its instruction set by being
// inlined into an entry point with that set's target attribute ([[gnu::flatten]], see
// simd_lanes.h), and without optimisation nothing is inlined: the kernel stays a function compiled
// for no vector set that passes vectors to the lanes' functions under another calling convention,
// and answers wrongly. A build without optimisation (-O0) therefore runs the scalar kernel only.
#ifdef __OPTIMIZE__
constexpr bool kVectorKernelsBuilt = true;
#else
constexpr bool kVectorKernelsBuilt = false;
#endif

// What the processor runs, asked once. __builtin_cpu_supports also checks that the operating
// system saves the wider registers (XGETBV), so a kernel it reports can run.
const std::array<bool, 3>& processor_runs() {
  static const std::array<bool, 3> runs = [] {
    __builtin_cpu_init();
    std::array<bool, 3> r{};
    r[index_of(Kernel::scalar)] = true;
    r[index_of(Kernel::avx2)] = kVectorKernelsBuilt && __builtin_cpu_supports("avx2");
    r[index_of(Kernel::avx512)] = kVectorKernelsBuilt && __builtin_cpu_supports("avx512f") &&
                                  __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
    return r;
  }();
  return runs;
}

}  // namespace

std::string_view to_string(Kernel k) {
  switch (k) {
    case Kernel::scalar: return "scalar";
    case Kernel::avx2: return "avx2";
    case Kernel::avx512: return "avx512";
  }
  return "?";
}

std::optional<Kernel> kernel_named(std::string_view name) {
  for (Kernel k : kAllKernels) {
    if (to_string(k) == name) return k;
  }
  return std::nullopt;
}

std::string_view features_needed(Kernel k) {
  switch (k) {
    case Kernel::scalar: return "none";
    case Kernel::avx2: return "AVX2";
    case Kernel::avx512: return "AVX-512 F, DQ and VL";
  }
  return "?";
}

bool supported(Kernel k) { return processor_runs()[index_of(k)]; }

std::vector<Kernel> supported_kernels() {
  std::vector<Kernel> out;
  for (Kernel k : kAllKernels) {
    if (supported(k)) out.push_back(k);
  }
  return out;
}

std::optional<std::string> unsupported_reason(Kernel k) {
  if (supported(k)) return std::nullopt;
  if (!kVectorKernelsBuilt) return "this build is not optimised, and the vector kernels need inlining (see simd.cpp)";
  return "this processor lacks " + std::string(features_needed(k));
}

namespace detail {

std::atomic<int> g_selected{-1};

Kernel choose() {
  const int forced = g_forced.load(std::memory_order_relaxed);
  static const Kernel best = supported_kernels().back();
  const Kernel k = forced >= 0 ? static_cast<Kernel>(forced) : best;
  g_selected.store(static_cast<int>(index_of(k)), std::memory_order_relaxed);
  return k;
}

}  // namespace detail

void force(std::optional<Kernel> k) {
  if (k) {
    if (const auto why = unsupported_reason(*k)) {
      throw std::invalid_argument("cannot force the " + std::string(to_string(*k)) + " kernel: " + *why);
    }
  }
  g_forced.store(k ? static_cast<int>(index_of(*k)) : -1, std::memory_order_relaxed);
  detail::choose();
}

ForcedKernel::ForcedKernel(Kernel k) {
  const int before = g_forced.load(std::memory_order_relaxed);
  if (before >= 0) previous_ = static_cast<Kernel>(before);
  force(k);
}

ForcedKernel::~ForcedKernel() { force(previous_); }

}  // namespace cc::simd
