#include "harness/model/query_kind.h"

#include <algorithm>

namespace cc::harness {

namespace {

#define CC_QUERY_KIND_NAME(name, Name) #name,
constexpr std::string_view kNames[] = {CC_FOR_EACH_QUERY_KIND(CC_QUERY_KIND_NAME)};
#undef CC_QUERY_KIND_NAME
static_assert(std::size(kNames) == kAllQueryKinds.size());

}  // namespace

std::string_view name(QueryKind kind) {
  const auto i = static_cast<std::size_t>(kind);
  return i < std::size(kNames) ? kNames[i] : "?";
}

std::optional<QueryKind> query_kind_named(std::string_view text) {
  for (QueryKind kind : kAllQueryKinds) {
    if (name(kind) == text) return kind;
  }
  return std::nullopt;
}

int longest_kind_name() {
  std::size_t longest = 0;
  for (QueryKind kind : kAllQueryKinds) longest = std::max(longest, name(kind).size());
  return static_cast<int>(longest);
}

}  // namespace cc::harness
