// The fields of a query's input, and of the parts inputs are made of, declared once: the case
// file's JSON (input_json.h), the fuzz record (fuzz_record.h), the shrinker's walk over values,
// the metamorphic relations' maps and the drawing of a case all read them from here.
//
// A kind's unit declares Fields<its input>; the parts kinds share declare theirs in
// model/parts.h. A type without Fields is a leaf, which each format knows how to handle (a
// double, a Vec3, a matrix as a frame or a rotation, a triangle, a point set, a mesh, ...).
#pragma once

#include <string_view>
#include <tuple>
#include <type_traits>

namespace cc::harness {

/// How a field's value is laid out where its type alone does not say.
struct Plain {};
struct AsFrame {};     // a Mat3: an orthonormal frame by its columns (a box's axes); any of the 48 signed permutations is a simple one
struct AsRotation {};  // a Mat3: a proper rotation by its rows (a pose); the 24 rotations of the cube are the simple ones
struct AsKdopK {};     // an int: the k of a k-DOP, one of 6, 14, 16, 18, 24, 26

namespace detail {
template <class M>
struct MemberPointer;
template <class C, class T>
struct MemberPointer<T C::*> {
  using Owner = C;
  using Type = T;
};
}  // namespace detail

/// A field: its name in a case file and the member that holds it. A part whose name is empty
/// stands in its owner's place: its own fields are written where the owner's are (a ray's
/// origin, dir, tmin and tmax at the top of a case of a ray against a box).
template <auto Member, class Layout = Plain>
struct Field {
  using Owner = typename detail::MemberPointer<decltype(Member)>::Owner;
  using Type = typename detail::MemberPointer<decltype(Member)>::Type;
  using As = Layout;
  std::string_view name;
  constexpr bool inline_part() const { return name.empty(); }
  static constexpr Type& of(Owner& owner) { return owner.*Member; }
  static constexpr const Type& of(const Owner& owner) { return owner.*Member; }
};

template <auto Member, class Layout = Plain>
constexpr Field<Member, Layout> field(std::string_view name) {
  return {name};
}

/// Fields<T>::list: the fields of T in order (a tuple of Field), for a type made of named parts.
template <class T>
struct Fields;

template <class T>
concept HasFields = requires { Fields<T>::list; };

/// Calls f(field) for each field of T, in order.
template <class T, class F>
constexpr void for_each_field(F&& f) {
  std::apply([&f](const auto&... fields) { (f(fields), ...); }, Fields<T>::list);
}

/// The index of T's field named `name`, or the number of fields when there is none.
template <class T>
consteval std::size_t field_index(std::string_view name) {
  std::size_t index = 0, found = std::tuple_size_v<std::decay_t<decltype(Fields<T>::list)>>;
  for_each_field<T>([&](const auto& f) {
    if (f.name == name && found == std::tuple_size_v<std::decay_t<decltype(Fields<T>::list)>>) found = index;
    ++index;
  });
  return found;
}

}  // namespace cc::harness
