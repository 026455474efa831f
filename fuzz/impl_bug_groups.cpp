#include "fuzz/impl_bug_groups.h"

#include <cstdio>
#include <cstdlib>

// Each group's function must keep a frame of its own on the stack: never inlined, never folded
// into another (each prints its own name), and not left by a tail call.
#if defined(__clang__)
#define CC_OWN_FRAME __attribute__((noinline, disable_tail_calls))
#else
#define CC_OWN_FRAME __attribute__((noinline, optimize("no-optimize-sibling-calls")))
#endif

namespace cc::fuzz {
namespace {

using harness::Disagreement;
using harness::QueryKind;

#define CC_GROUP_FUNCTION(d, kind)                                        \
  [[noreturn]] CC_OWN_FRAME void impl_bug_##kind##_##d() {                \
    std::fputs("impl_bug group " #kind "." #d "\n", stderr);              \
    std::abort();                                                         \
  }
#define CC_KIND_GROUP_FUNCTIONS(kind, Kind) CC_FOR_EACH_DISAGREEMENT(CC_GROUP_FUNCTION, kind)
CC_FOR_EACH_QUERY_KIND(CC_KIND_GROUP_FUNCTIONS)
#undef CC_KIND_GROUP_FUNCTIONS
#undef CC_GROUP_FUNCTION

}  // namespace

void abort_in_group(QueryKind kind, Disagreement d) {
#define CC_GROUP_CASE(d, kind) \
  case Disagreement::d: impl_bug_##kind##_##d();
#define CC_KIND_CASE(kind, Kind)                            \
  case QueryKind::kind:                                     \
    switch (d) { CC_FOR_EACH_DISAGREEMENT(CC_GROUP_CASE, kind) } \
    break;
  switch (kind) { CC_FOR_EACH_QUERY_KIND(CC_KIND_CASE) }
#undef CC_KIND_CASE
#undef CC_GROUP_CASE
  std::abort();
}

}  // namespace cc::fuzz
