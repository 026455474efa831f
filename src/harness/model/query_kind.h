// The kinds of query the harness checks, from the registry (model/registry.h). Their names are
// used everywhere: on the command line, in case files and as folder names under corpora/.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "harness/model/registry.h"

namespace cc::harness {

#define CC_QUERY_KIND_ENUMERATOR(name, Name) name,
enum class QueryKind { CC_FOR_EACH_QUERY_KIND(CC_QUERY_KIND_ENUMERATOR) };
#undef CC_QUERY_KIND_ENUMERATOR

#define CC_QUERY_KIND_VALUE(name, Name) QueryKind::name,
inline constexpr std::array kAllQueryKinds = {CC_FOR_EACH_QUERY_KIND(CC_QUERY_KIND_VALUE)};
#undef CC_QUERY_KIND_VALUE


/// The query's name, as the registry gives it.
std::string_view name(QueryKind kind);

/// The query with that name, if any.
std::optional<QueryKind> query_kind_named(std::string_view name);

/// The length of the longest kind's name: the width of a table's column of kinds.
int longest_kind_name();

}  // namespace cc::harness
