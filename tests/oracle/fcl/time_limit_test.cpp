// The time limit of FCL's calls (oracle/fcl/time_limit.h): a call that never returns is abandoned
// at its limit, one that aborts is abandoned at once, one that returns is not, and abandoning a
// call while it is inside the allocator leaves the heap whole.
#include "oracle/fcl/time_limit.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

namespace cc::fcl_oracle {
namespace {

TEST(RunGuarded, TellsReturnedTimedOutAndAbortedApart) {
  int calls = 0;
  EXPECT_EQ(run_guarded(1, [&] { ++calls; }), Guarded::returned);
  EXPECT_EQ(calls, 1);
  volatile bool forever = true;
  EXPECT_EQ(run_guarded(0.01, [&] {
              while (forever) {
              }
            }),
            Guarded::timed_out);
  EXPECT_EQ(run_guarded(1, [] { std::abort(); }), Guarded::aborted);
  EXPECT_FALSE(run_with_time_limit(0.01, [&] {
    while (forever) {
    }
  }));
}

// A call that spends much of its time in malloc and free (and the rest filling what it got),
// abandoned at its limit 100 times: a jump out of the middle of malloc would leave its lists
// broken, and glibc aborts on the next allocation that meets them (in a later call, or after the
// loop). The jump waits until the call is in its own code.
TEST(RunGuarded, AbandonsACallBusyInTheAllocatorWithTheHeapWhole) {
  int timed_out = 0;
  for (int i = 0; i < 100; ++i) {
    const Guarded g = run_guarded(0.002, [] {
      void* held[32] = {};
      for (unsigned n = 1;; n = n * 7 % 509 + 1) {
        std::free(held[n % 32]);
        held[n % 32] = std::malloc(n * 8);
        auto* words = static_cast<volatile double*>(held[n % 32]);
        for (unsigned k = 0; k < n; ++k) words[k] = k;
      }
    });
    timed_out += g == Guarded::timed_out;
  }
  EXPECT_EQ(timed_out, 100);
  std::vector<void*> blocks;
  for (std::size_t n = 1; n < 200000; n += 131) blocks.push_back(std::malloc(n));
  for (void* b : blocks) std::free(b);
  EXPECT_GE(abandoned_calls(), 100);
}

}  // namespace
}  // namespace cc::fcl_oracle
