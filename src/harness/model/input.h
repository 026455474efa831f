// The inputs of one query of each kind: a variant over the kinds' input types, in the order of
// the registry (kinds/registry.h), so that an input's index is its QueryKind.
#pragma once

#include <type_traits>
#include <utility>
#include <variant>

#include "harness/model/query_kind.h"

namespace cc::harness {

namespace detail {
template <class First, class... Rest>
struct VariantOfRest {
  using type = std::variant<Rest...>;
};
}  // namespace detail

#define CC_QUERY_KIND_INPUT(name, Name) , Name##Input
/// The inputs of a query of any kind.
using Input = detail::VariantOfRest<void CC_FOR_EACH_QUERY_KIND(CC_QUERY_KIND_INPUT)>::type;
#undef CC_QUERY_KIND_INPUT

/// The input type of a kind.
template <QueryKind K>
using InputOf = std::variant_alternative_t<static_cast<std::size_t>(K), Input>;

#define CC_QUERY_KIND_CHECK(name, Name) \
  static_assert(std::is_same_v<InputOf<QueryKind::name>, Name##Input>, "the Input variant follows QueryKind");
CC_FOR_EACH_QUERY_KIND(CC_QUERY_KIND_CHECK)
#undef CC_QUERY_KIND_CHECK
static_assert(std::variant_size_v<Input> == kAllQueryKinds.size(), "every input type is a kind's");

// Every kind's unit has every piece (kinds/query.h).
#define CC_QUERY_KIND_UNIT(name, Name) static_assert(QueryUnit<Name##Input>, "the unit of " #name " lacks a piece");
CC_FOR_EACH_QUERY_KIND(CC_QUERY_KIND_UNIT)
#undef CC_QUERY_KIND_UNIT

inline QueryKind kind_of(const Input& input) { return static_cast<QueryKind>(input.index()); }

/// Calls f.template operator()<In>() with the input type of the kind.
template <class F>
decltype(auto) with_kind(QueryKind kind, F&& f) {
  switch (kind) {
#define CC_QUERY_KIND_CASE(name, Name) \
  case QueryKind::name: return f.template operator()<Name##Input>();
    CC_FOR_EACH_QUERY_KIND(CC_QUERY_KIND_CASE)
#undef CC_QUERY_KIND_CASE
  }
  return f.template operator()<InputOf<kAllQueryKinds.front()>>();  // never: every kind has a case
}

/// The two placed meshes of a query on them; nothing for other kinds.
inline const MeshPair* meshes_of(const Input& input) {
  return std::visit(
      []<class In>(const In& in) -> const MeshPair* {
        if constexpr (requires { in.meshes; }) {
          return &in.meshes;
        } else {
          return nullptr;
        }
      },
      input);
}

}  // namespace cc::harness
