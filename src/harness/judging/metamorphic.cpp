#include "harness/judging/metamorphic.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "harness/model/parts.h"
#include "harness/generation/choices.h"
#include "harness/model/kind_pieces.h"

namespace cc::harness {
namespace {

constexpr int kPermutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

// One of the 6 orders of three things, for any int.
const int* order_of(long parameter) { return kPermutations[((parameter % 6) + 6) % 6]; }

// A shuffle of n things from a seed: place[i] is where thing i goes.
std::vector<std::uint32_t> shuffle_of(std::size_t n, int parameter, std::uint64_t salt) {
  std::vector<std::uint32_t> place(n);
  for (std::uint32_t i = 0; i < n; ++i) place[i] = i;
  std::uint64_t state = mix_seed(static_cast<std::uint64_t>(static_cast<std::uint32_t>(parameter)), salt);
  for (std::size_t i = n; i > 1; --i) {
    state = mix_seed(state, i);
    std::swap(place[i - 1], place[state % i]);
  }
  return place;
}

// Salts of the shuffles, so that two meshes or two point sets are shuffled differently.
constexpr std::uint64_t kSaltA = 0xa, kSaltB = 0xb;

Triangle reordered(const Triangle& t, long parameter) {
  const int* o = order_of(parameter);
  return {{t.v[o[0]], t.v[o[1]], t.v[o[2]]}};
}

// A mesh with its faces moved by a shuffle, or each face's vertices reordered (face f by
// parameter + f), given by its triangles.
MeshRef reordered(const MeshRef& ref, Relation relation, int parameter, std::uint64_t salt) {
  Mesh m = *ref.mesh;
  if (relation == Relation::permute_faces) {
    const std::vector<std::uint32_t> place = shuffle_of(m.faces.size(), parameter, salt);
    for (std::size_t f = 0; f < place.size(); ++f) m.faces[place[f]] = ref.mesh->faces[f];
  } else {
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      const int* o = order_of(parameter + static_cast<long>(f));
      m.faces[f] = {ref.mesh->faces[f][o[0]], ref.mesh->faces[f][o[1]], ref.mesh->faces[f][o[2]]};
    }
  }
  return triangles_mesh(std::move(m));
}

template <class T>
std::vector<T> shuffled(const std::vector<T>& items, int parameter, std::uint64_t salt) {
  const std::vector<std::uint32_t> place = shuffle_of(items.size(), parameter, salt);
  std::vector<T> out(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) out[place[i]] = items[i];
  return out;
}

// One relation as maps on the parts of a query, by their types. `ok` turns false when a value
// cannot be mapped exactly. The reorderings count the parts they meet: the i-th triangle takes
// its vertex order from parameter / 6^i, the i-th point set and mesh their shuffles from salt
// kSaltA + i.
struct Map {
  Relation relation;
  int parameter;
  bool ok = true;
  int triangles = 0, point_sets = 0, meshes = 0, walls = 0, lists = 0;

  double length(double x) {
    if (relation != Relation::scale || x == 0 || !std::isfinite(x)) return x;
    const double y = std::ldexp(x, parameter);
    if (!std::isfinite(y) || std::ldexp(y, -parameter) != x || std::fabs(y) < 0x1p-1022) ok = false;
    return y;
  }
  Vec3 point(const Vec3& p) {
    switch (relation) {
      case Relation::permute_axes: {
        const int* perm = kPermutations[parameter];
        return {p[perm[0]], p[perm[1]], p[perm[2]]};
      }
      case Relation::flip_axis: {
        Vec3 q = p;
        q[parameter] = -q[parameter];
        return q;
      }
      case Relation::scale: return {length(p.x), length(p.y), length(p.z)};
      default: return p;  // swapping and reordering move no coordinate
    }
  }
  // A point of the plane z = 0: x and y swapped when the permutation puts y before x, one of them
  // negated (flipping z leaves the plane as it is).
  Vec2 point(const Vec2& p) {
    switch (relation) {
      case Relation::permute_axes: {
        const int* perm = kPermutations[parameter];
        const auto place = [perm](int axis) { return std::find(perm, perm + 3, axis) - perm; };
        return place(1) < place(0) ? Vec2{p.y, p.x} : p;
      }
      case Relation::flip_axis: return {parameter == 0 ? -p.x : p.x, parameter == 1 ? -p.y : p.y};
      case Relation::scale: return {length(p.x), length(p.y)};
      default: return p;
    }
  }
  // A direction that does not scale (rotation columns).
  Vec3 direction(const Vec3& d) { return relation == Relation::scale ? d : point(d); }

  void map(Vec3& p, Plain) { p = point(p); }
  void map(Aabb& b, Plain) {
    Aabb r{point(b.lo), point(b.hi)};
    if (relation == Relation::flip_axis) std::swap(r.lo[parameter], r.hi[parameter]);
    b = r;
  }
  void map(Obb& b, Plain) {
    Obb r;
    r.center = point(b.center);
    r.half = {length(b.half.x), length(b.half.y), length(b.half.z)};
    for (int j = 0; j < 3; ++j) r.axes.col[j] = direction(b.axes.col[j]);
    b = r;
  }
  void map(Sphere& s, Plain) { s = {point(s.center), length(s.radius)}; }
  void map(Vec2& p, Plain) { p = point(p); }
  void map(Disc& d, Plain) { d = {point(d.center), length(d.radius)}; }
  // Reordering a wall's ends: the i-th wall's swapped when its bit of the parameter's hash is set.
  void map(Wall& w, Plain) {
    const auto index = static_cast<std::uint64_t>(walls++);
    if (relation == Relation::permute_vertices) {
      if (mix_seed(static_cast<std::uint32_t>(parameter), kSaltA + index) & 1) std::swap(w.a, w.b);
      return;
    }
    w = {point(w.a), point(w.b)};
  }
  // A ray's direction scales with it: t stays the same.
  void map(Ray& r, Plain) { r.origin = point(r.origin), r.dir = point(r.dir); }
  // A pose: the world's axes permuted permute the rows of its rotation (as its columns' points).
  void map(RigidTransform& t, Plain) {
    for (int j = 0; j < 3; ++j) t.rotation.col[j] = point(t.rotation.col[j]);
    t.translation = point(t.translation);
  }
  void map(Triangle& t, Plain) {
    long order = parameter;
    for (int i = 0; i < triangles; ++i) order /= 6;
    ++triangles;
    if (relation == Relation::permute_vertices) {
      t = reordered(t, order);
    } else {
      t = {{point(t.v[0]), point(t.v[1]), point(t.v[2])}};
    }
  }
  void map(std::vector<Vec3>& points, Plain) {
    const std::uint64_t salt = kSaltA + static_cast<std::uint64_t>(point_sets++);
    if (relation == Relation::permute_points) {
      points = shuffled(points, parameter, salt);
      return;
    }
    for (Vec3& p : points) p = point(p);
  }
  void map(MeshRef& mesh, Plain) {
    const std::uint64_t salt = kSaltA + static_cast<std::uint64_t>(meshes++);
    if (relation == Relation::permute_faces || relation == Relation::permute_vertices) mesh = reordered(mesh, relation, parameter, salt);
  }
  void map(BoxFrames& frames, Plain) {
    if (relation == Relation::permute_objects) {
      for (auto& frame : frames) frame = shuffled(frame, parameter, kSaltA);
      return;
    }
    for (auto& frame : frames) {
      for (auto& b : frame) {
        if (b) map(*b, Plain{});
      }
    }
  }
  void map(int&, AsKdopK) {}
  void map(LibraryBvh&, Plain) {}
  template <HasFields T>
  void map(T& value, Plain);
  // A list of parts (a maze's walls): reordered as objects are (the i-th list shuffled from salt
  // kSaltA + i), or each part mapped.
  template <PartList L>
  void map(L& parts, Plain) {
    const std::uint64_t salt = kSaltA + static_cast<std::uint64_t>(lists++);
    if (relation == Relation::permute_objects) {
      parts = shuffled(parts, parameter, salt);
      return;
    }
    for (auto& part : parts) map(part, Plain{});
  }
};

template <HasFields T>
void Map::map(T& value, Plain) {
  for_each_field<T>([&](const auto& f) {
    using F = std::decay_t<decltype(f)>;
    map(F::of(value), typename F::As{});
  });
}

// The input with its fields named a and b exchanged.
template <class In>
In swapped(In in) {
  constexpr std::size_t a = field_index<In>("a"), b = field_index<In>("b");
  static_assert(a != b && b < std::tuple_size_v<std::decay_t<decltype(Fields<In>::list)>>, "swapping needs fields a and b");
  using A = std::decay_t<decltype(std::get<a>(Fields<In>::list))>;
  using B = std::decay_t<decltype(std::get<b>(Fields<In>::list))>;
  static_assert(std::is_same_v<typename A::Type, typename B::Type>, "swapping needs a and b of one type");
  std::swap(A::of(in), B::of(in));
  return in;
}

double flush(double x) {
  const double m = std::fabs(x);
  return (std::isfinite(x) && x != 0 && (m < 0x1p-250 || m > 0x1p250)) ? 0.0 : x;
}

// Every value flushed, but a mesh's (whose cases are never scaled).
struct Flush {
  void map(double& x, Plain) { x = flush(x); }
  void map(Vec3& v, Plain) { v = {flush(v.x), flush(v.y), flush(v.z)}; }
  void map(Vec2& v, Plain) { v = {flush(v.x), flush(v.y)}; }
  void map(Mat3& m, AsFrame) {
    for (Vec3& c : m.col) map(c, Plain{});
  }
  void map(Triangle& t, Plain) {
    for (Vec3& p : t.v) map(p, Plain{});
  }
  void map(std::vector<Vec3>& points, Plain) {
    for (Vec3& p : points) map(p, Plain{});
  }
  void map(BoxFrames& frames, Plain) {
    for (auto& frame : frames) {
      for (auto& b : frame) {
        if (b) map(*b, Plain{});
      }
    }
  }
  void map(MeshPair&, Plain) {}
  void map(MeshRef&, Plain) {}
  void map(LibraryBvh&, Plain) {}
  void map(int&, AsKdopK) {}
  template <HasFields T>
  void map(T& value, Plain);
  template <PartList L>
  void map(L& parts, Plain) {
    for (auto& part : parts) map(part, Plain{});
  }
};

template <HasFields T>
void Flush::map(T& value, Plain) {
  for_each_field<T>([&](const auto& f) {
    using F = std::decay_t<decltype(f)>;
    map(F::of(value), typename F::As{});
  });
}

// Where the reorderings move the answer's faces and slots: the i-th mesh renames the i-th face
// of every pair; boxes over frames rename the slots of every frame's pairs; a list of parts (the
// first) renames the first of every pair (a wall touched is (wall, 0)).
struct Rename {
  Answer& out;
  Relation relation;
  int parameter;
  int meshes = 0, lists = 0;

  static void rename(std::vector<FacePair>& pairs, const auto& map) {
    for (FacePair& p : pairs) p = map(p);
    std::sort(pairs.begin(), pairs.end());
  }
  void at(const MeshRef& mesh, Plain) {
    const int index = meshes++;
    if (relation != Relation::permute_faces || index > 1) return;
    const auto place = shuffle_of(mesh.mesh->size(), parameter, kSaltA + static_cast<std::uint64_t>(index));
    std::uint32_t FacePair::*face = index == 0 ? &FacePair::first : &FacePair::second;
    rename(out.pairs, [&](FacePair p) {
      p.*face = place[p.*face];
      return p;
    });
  }
  void at(const BoxFrames& frames, Plain) {
    if (relation != Relation::permute_objects) return;
    const auto place = shuffle_of(frames.empty() ? 0 : frames[0].size(), parameter, kSaltA);
    for (auto& frame : out.frames) rename(frame, [&](const FacePair& p) { return std::minmax(place[p.first], place[p.second]); });
  }
  template <PartList L>
  void at(const L& parts, Plain) {
    const int index = lists++;
    if (relation != Relation::permute_objects || index > 0) return;
    const auto place = shuffle_of(parts.size(), parameter, kSaltA + static_cast<std::uint64_t>(index));
    rename(out.pairs, [&](FacePair p) {
      p.first = place[p.first];
      return p;
    });
  }
  template <class T, class As>
  void at(const T& value, As) {
    if constexpr (HasFields<T>) {
      for_each_field<T>([&](const auto& f) {
        using F = std::decay_t<decltype(f)>;
        at(F::of(value), typename F::As{});
      });
    }
  }
};

}  // namespace

bool relation_applies(QueryKind kind, Relation relation) {
  return pieces_of(kind).relations.has(relation);
}

std::optional<Input> transform(const Input& input, Relation relation, int parameter) {
  const KindPieces& pieces = pieces_of(kind_of(input));
  if (!pieces.relations.has(relation) || !pieces.admits(input, relation)) return std::nullopt;
  return std::visit(
      [&]<class In>(const In& in) -> std::optional<Input> {
        if (relation == Relation::swap_shapes) {
          if constexpr (field_index<In>("b") < std::tuple_size_v<std::decay_t<decltype(Fields<In>::list)>>) return swapped(in);
          return std::nullopt;
        }
        Map map{relation, parameter};
        In out = in;
        map.map(out, Plain{});
        if (!map.ok) return std::nullopt;
        return out;
      },
      input);
}

Input flush_extremes(const Input& input) {
  return std::visit(
      [](const auto& in) -> Input {
        auto out = in;
        Flush{}.map(out, Plain{});
        return out;
      },
      input);
}

Answer mapped_answer(const Answer& answer, const Input& original, Relation relation, int parameter) {
  Answer out = answer;
  std::visit([&](const auto& in) { Rename{out, relation, parameter}.at(in, Plain{}); }, original);
  return out;
}

}  // namespace cc::harness
