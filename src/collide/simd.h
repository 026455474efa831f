// The SIMD kernels of the library's batched routines: which instruction sets they are written
// for, which of them this processor runs, and which one the routines use. By default that is the
// best the processor has; a kernel can be forced (for the whole process) so that tests run every
// kernel the machine supports against the scalar one.
#pragma once

#include <atomic>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cc::simd {

/// A kernel of a batched routine, by instruction set. Every batched routine has all of them,
/// and they give the same answers bit for bit (the same IEEE double arithmetic in each lane).
enum class Kernel { scalar, avx2, avx512 };
inline constexpr Kernel kAllKernels[] = {Kernel::scalar, Kernel::avx2, Kernel::avx512};

/// "scalar", "avx2", "avx512".
std::string_view to_string(Kernel k);
/// The kernel with that name, if any.
std::optional<Kernel> kernel_named(std::string_view name);
/// The processor features a kernel needs, e.g. "AVX-512 F, DQ and VL"; "none" for scalar.
std::string_view features_needed(Kernel k);

/// Whether this processor (and its operating system) runs the kernel, checked at run time, and
/// this build has it: a build without optimisation (-O0) has the scalar kernel only. Always true
/// for scalar.
bool supported(Kernel k);
/// The kernels this processor runs, scalar first.
std::vector<Kernel> supported_kernels();
/// Why the kernel cannot run ("this processor lacks AVX2", or a build without optimisation), or
/// nothing.
std::optional<std::string> unsupported_reason(Kernel k);

namespace detail {
/// What selected() returns, as an index into kAllKernels; -1 until it is first asked.
extern std::atomic<int> g_selected;
/// Sets g_selected from the forced kernel, or else the best supported one, and returns it.
Kernel choose();
}  // namespace detail

/// The kernel batched routines use: the forced one, if any, else the best supported. Inline and
/// cheap (one load), so that a test called per pair can dispatch on it.
inline Kernel selected() {
  const int k = detail::g_selected.load(std::memory_order_relaxed);
  return k >= 0 ? static_cast<Kernel>(k) : detail::choose();
}

/// Makes every batched routine use `k` from now on, in every thread (nothing: the best supported
/// again). A call already running finishes with the kernel it started with. Throws
/// std::invalid_argument (with unsupported_reason) if this processor cannot run `k`.
void force(std::optional<Kernel> k);

/// Forces a kernel for its lifetime, then restores the choice before it.
class ForcedKernel {
 public:
  explicit ForcedKernel(Kernel k);
  ~ForcedKernel();
  ForcedKernel(const ForcedKernel&) = delete;
  ForcedKernel& operator=(const ForcedKernel&) = delete;

 private:
  std::optional<Kernel> previous_;
};

}  // namespace cc::simd
