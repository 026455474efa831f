// The inputs of one query of each kind: a variant over the kinds' input types, in the order of
// the registry (model/registry.h), so that an input's index is its QueryKind.
#pragma once

#include <optional>
#include <stdexcept>
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

/// What a query on two placed meshes asks of them (every colliding pair of triangles, or the
/// first one found); nothing for other kinds.
inline std::optional<CollisionMode> mesh_mode_of(const Input& input) {
  return std::visit(
      []<class In>(const In&) -> std::optional<CollisionMode> {
        if constexpr (requires { In::mode; &In::meshes; }) {
          return In::mode;
        } else {
          return std::nullopt;
        }
      },
      input);
}

/// The kind that asks `mode` of two placed meshes (found in the registry: the kind whose input is
/// the two meshes and says what it asks). Throws std::invalid_argument when no kind asks it.
inline QueryKind mesh_kind(CollisionMode mode) {
  for (QueryKind kind : kAllQueryKinds) {
    const bool asks = with_kind(kind, [mode]<class In>() {
      if constexpr (requires { In::mode; &In::meshes; }) {
        return In::mode == mode;
      } else {
        return false;
      }
    });
    if (asks) return kind;
  }
  throw std::invalid_argument("no query kind asks this of two meshes");
}

namespace detail {
template <class In>
concept FramesOfBoxesAlone = requires(In in) {
  requires std::same_as<decltype(In::frames), BoxFrames>;
  requires std::tuple_size_v<std::remove_cvref_t<decltype(Fields<In>::list)>> == 1;
};
template <class In>
concept DiscAndWallsAlone = requires(In in) {
  requires std::same_as<decltype(In::disc), Disc>;
  requires std::same_as<decltype(In::walls), std::vector<Wall>>;
  requires std::tuple_size_v<std::remove_cvref_t<decltype(Fields<In>::list)>> == 2;
};

// The input of the one kind whose input type satisfies Is, made by `make` (exactly one kind's
// does, or this does not compile).
template <template <class> class Is, class Make>
Input the_input_where(Make&& make) {
  return [&make]<std::size_t... I>(std::index_sequence<I...>) {
    static_assert((std::size_t{Is<std::variant_alternative_t<I, Input>>::value} + ...) == 1,
                  "exactly one kind has such an input");
    Input out;
    (
        [&]<class In>(std::type_identity<In>) {
          if constexpr (Is<In>::value) out = make(std::type_identity<In>{});
        }(std::type_identity<std::variant_alternative_t<I, Input>>{}),
        ...);
    return out;
  }(std::make_index_sequence<std::variant_size_v<Input>>{});
}
template <class In>
struct IsFramesOfBoxesAlone : std::bool_constant<FramesOfBoxesAlone<In>> {};
template <class In>
struct IsDiscAndWallsAlone : std::bool_constant<DiscAndWallsAlone<In>> {};
}  // namespace detail

/// The input of the kind asked of a set of boxes over frames (the kind whose input is the frames
/// alone; exactly one is, or this does not compile).
inline Input box_frames_input(BoxFrames frames) {
  return detail::the_input_where<detail::IsFramesOfBoxesAlone>([&frames]<class In>(std::type_identity<In>) {
    return In{std::move(frames)};
  });
}

/// The input of the kind asked of a disc against walls (the kind whose input is the disc and the
/// walls alone; exactly one is, or this does not compile).
inline Input disc_and_walls_input(Disc disc, std::vector<Wall> walls) {
  return detail::the_input_where<detail::IsDiscAndWallsAlone>([&disc, &walls]<class In>(std::type_identity<In>) {
    return In{disc, std::move(walls)};
  });
}

}  // namespace cc::harness
