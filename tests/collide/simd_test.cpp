#include "collide/simd.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace cc::simd {
namespace {

TEST(Simd, NamesRoundTrip) {
  for (Kernel k : kAllKernels) EXPECT_EQ(kernel_named(to_string(k)), k);
  EXPECT_EQ(kernel_named("avx512"), Kernel::avx512);
  EXPECT_EQ(kernel_named("sse2"), std::nullopt);
  EXPECT_EQ(kernel_named(""), std::nullopt);
}

// The test log says which kernels this machine runs (the others are skipped by the kernel tests).
TEST(Simd, ScalarAlwaysRunsAndTheBestSupportedIsTheDefault) {
  const std::vector<Kernel> kernels = supported_kernels();
  ASSERT_FALSE(kernels.empty());
  EXPECT_EQ(kernels.front(), Kernel::scalar);
  EXPECT_TRUE(supported(Kernel::scalar));
  EXPECT_EQ(unsupported_reason(Kernel::scalar), std::nullopt);
  for (Kernel k : kAllKernels) {
    std::printf("kernel %-7s %s\n", std::string(to_string(k)).c_str(),
                supported(k) ? "runs on this processor" : unsupported_reason(k)->c_str());
    EXPECT_EQ(supported(k), !unsupported_reason(k).has_value());
  }
  EXPECT_EQ(selected(), kernels.back());
}

TEST(Simd, AForcedKernelIsUsedUntilItsScopeEnds) {
  const Kernel best = selected();
  for (Kernel k : supported_kernels()) {
    {
      const ForcedKernel forced(k);
      EXPECT_EQ(selected(), k);
      {
        const ForcedKernel inner(Kernel::scalar);
        EXPECT_EQ(selected(), Kernel::scalar);
      }
      EXPECT_EQ(selected(), k);  // the outer choice again
    }
    EXPECT_EQ(selected(), best);
  }
  force(Kernel::scalar);
  EXPECT_EQ(selected(), Kernel::scalar);
  force(std::nullopt);
  EXPECT_EQ(selected(), best);
}

// The reason a kernel cannot run: the processor, or a build without optimisation, which has the
// scalar kernel only (its vector kernels would not be inlined into their instruction set's code).
TEST(Simd, AnUnsupportedKernelSaysWhy) {
  for (Kernel k : kAllKernels) {
    if (supported(k)) continue;
    const std::string why = unsupported_reason(k).value();
#ifdef __OPTIMIZE__
    EXPECT_EQ(why, "this processor lacks " + std::string(features_needed(k)));
#else
    EXPECT_NE(why.find("not optimised"), std::string::npos) << why;
#endif
  }
#ifndef __OPTIMIZE__
  EXPECT_EQ(supported_kernels(), std::vector<Kernel>{Kernel::scalar});
#endif
}

TEST(Simd, AKernelTheProcessorLacksCannotBeForced) {
  for (Kernel k : kAllKernels) {
    if (supported(k)) continue;
    try {
      force(k);
      ADD_FAILURE() << to_string(k) << " was forced on a processor that lacks it";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(*unsupported_reason(k)), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(supported(selected()));  // a failed force changes nothing
}

}  // namespace
}  // namespace cc::simd
