#include "harness/judging/metamorphic.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "harness/generation/choices.h"

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

// One relation as maps on the parts of a query. `ok` turns false when a value cannot be mapped
// exactly.
struct Map {
  Relation relation;
  int parameter;
  bool ok = true;

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
  // A direction that does not scale (rotation columns).
  Vec3 direction(const Vec3& d) { return relation == Relation::scale ? d : point(d); }
  Aabb box(const Aabb& b) {
    Aabb r{point(b.lo), point(b.hi)};
    if (relation == Relation::flip_axis) std::swap(r.lo[parameter], r.hi[parameter]);
    return r;
  }
  Obb obb(const Obb& b) {
    Obb r;
    r.center = point(b.center);
    r.half = {length(b.half.x), length(b.half.y), length(b.half.z)};
    for (int j = 0; j < 3; ++j) r.axes.col[j] = direction(b.axes.col[j]);
    return r;
  }
  Triangle triangle(const Triangle& t) { return {{point(t.v[0]), point(t.v[1]), point(t.v[2])}}; }
  Sphere sphere(const Sphere& s) { return {point(s.center), length(s.radius)}; }

  std::optional<Input> operator()(const RayAabbInput& in) {
    RayAabbInput r = in;
    r.ray.origin = point(in.ray.origin);
    r.ray.dir = point(in.ray.dir);  // scaled too: t stays the same
    r.box = box(in.box);
    return r;
  }
  std::optional<Input> operator()(const SphereSphereInput& in) {
    if (relation == Relation::swap_shapes) return SphereSphereInput{in.b, in.a};
    return SphereSphereInput{sphere(in.a), sphere(in.b)};
  }
  std::optional<Input> operator()(const AabbAabbInput& in) {
    if (relation == Relation::swap_shapes) return AabbAabbInput{in.b, in.a};
    return AabbAabbInput{box(in.a), box(in.b)};
  }
  std::optional<Input> operator()(const KdopKdopInput& in) {
    if (relation == Relation::swap_shapes) return KdopKdopInput{in.k, in.b, in.a};
    if (relation == Relation::permute_points) {
      return KdopKdopInput{in.k, shuffled(in.a, parameter, kSaltA), shuffled(in.b, parameter, kSaltB)};
    }
    if (relation == Relation::permute_axes && in.k == 16) return std::nullopt;
    if (relation == Relation::flip_axis && (in.k == 16 || in.k == 24)) return std::nullopt;
    KdopKdopInput r{in.k, {}, {}};
    for (const Vec3& p : in.a) r.a.push_back(point(p));
    for (const Vec3& p : in.b) r.b.push_back(point(p));
    return r;
  }
  std::optional<Input> operator()(const ObbObbInput& in) {
    if (relation == Relation::swap_shapes) return ObbObbInput{in.b, in.a};
    return ObbObbInput{obb(in.a), obb(in.b)};
  }
  std::optional<Input> operator()(const TriAabbInput& in) {
    if (relation == Relation::permute_vertices) return TriAabbInput{reordered(in.tri, parameter), in.box};
    return TriAabbInput{triangle(in.tri), box(in.box)};
  }
  std::optional<Input> operator()(const TriObbInput& in) {
    if (relation == Relation::permute_vertices) return TriObbInput{reordered(in.tri, parameter), in.box};
    return TriObbInput{triangle(in.tri), obb(in.box)};
  }
  std::optional<Input> operator()(const TriTriInput& in) {
    if (relation == Relation::swap_shapes) return TriTriInput{in.b, in.a};
    if (relation == Relation::permute_vertices) {
      return TriTriInput{reordered(in.a, parameter), reordered(in.b, parameter / 6)};
    }
    return TriTriInput{triangle(in.a), triangle(in.b)};
  }
  std::optional<Input> operator()(const BroadphaseInput& in) {
    if (relation == Relation::permute_objects) {
      BroadphaseInput r;
      for (const auto& frame : in.frames) r.frames.push_back(shuffled(frame, parameter, kSaltA));
      return r;
    }
    BroadphaseInput r = in;
    for (auto& frame : r.frames) {
      for (auto& b : frame) {
        if (b) b = box(*b);
      }
    }
    return r;
  }
  std::optional<Input> operator()(const RayMeshInput& in) {
    return RayMeshInput{reordered(in.mesh, relation, parameter, kSaltA), in.ray, in.library};
  }
  std::optional<Input> operator()(const MovingObbInput& in) {
    if (relation == Relation::swap_shapes) return MovingObbInput{in.b, in.a};
    return MovingObbInput{{obb(in.a.box), point(in.a.velocity)}, {obb(in.b.box), point(in.b.velocity)}};
  }
  // Meshes: the world's axes permuted, which permutes the rows of both poses (the relative
  // transform, and with it every computation of the library, is unchanged bit for bit); or
  // their faces, or each face's vertices, reordered.
  std::optional<Input> operator()(const MeshMeshInput& in) { return meshes(in.meshes, MeshMeshInput{}); }
  std::optional<Input> operator()(const MeshMeshFirstInput& in) { return meshes(in.meshes, MeshMeshFirstInput{}); }
  template <class Query>
  std::optional<Input> meshes(const MeshPair& m, Query out) {
    out.meshes = m;
    if (relation == Relation::permute_faces || relation == Relation::permute_vertices) {
      out.meshes.a = reordered(m.a, relation, parameter, kSaltA);
      out.meshes.b = reordered(m.b, relation, parameter, kSaltB);
      return out;
    }
    for (RigidTransform* pose : {&out.meshes.pose_a, &out.meshes.pose_b}) {
      for (int j = 0; j < 3; ++j) pose->rotation.col[j] = point(pose->rotation.col[j]);
      pose->translation = point(pose->translation);
    }
    return out;
  }
};

double flush(double x) {
  const double m = std::fabs(x);
  return (std::isfinite(x) && x != 0 && (m < 0x1p-250 || m > 0x1p250)) ? 0.0 : x;
}
Vec3 flush(const Vec3& v) { return {flush(v.x), flush(v.y), flush(v.z)}; }
Mat3 flush(const Mat3& m) { return Mat3::from_columns(flush(m.col[0]), flush(m.col[1]), flush(m.col[2])); }
Aabb flush(const Aabb& b) { return {flush(b.lo), flush(b.hi)}; }
Obb flush(const Obb& b) { return {flush(b.center), flush(b.half), flush(b.axes)}; }
Triangle flush(const Triangle& t) { return {{flush(t.v[0]), flush(t.v[1]), flush(t.v[2])}}; }
Sphere flush(const Sphere& s) { return {flush(s.center), flush(s.radius)}; }

struct Flush {
  Input operator()(const RayAabbInput& in) const {
    RayAabbInput r = in;
    r.ray.origin = flush(in.ray.origin);
    r.ray.dir = flush(in.ray.dir);
    r.ray.tmin = flush(in.ray.tmin);  // the library scales t with the direction
    r.ray.tmax = flush(in.ray.tmax);
    r.box = flush(in.box);
    return r;
  }
  Input operator()(const SphereSphereInput& in) const { return SphereSphereInput{flush(in.a), flush(in.b)}; }
  Input operator()(const AabbAabbInput& in) const { return AabbAabbInput{flush(in.a), flush(in.b)}; }
  Input operator()(const KdopKdopInput& in) const {
    KdopKdopInput r{in.k, {}, {}};
    for (const Vec3& p : in.a) r.a.push_back(flush(p));
    for (const Vec3& p : in.b) r.b.push_back(flush(p));
    return r;
  }
  Input operator()(const ObbObbInput& in) const { return ObbObbInput{flush(in.a), flush(in.b)}; }
  Input operator()(const TriAabbInput& in) const { return TriAabbInput{flush(in.tri), flush(in.box)}; }
  Input operator()(const TriObbInput& in) const { return TriObbInput{flush(in.tri), flush(in.box)}; }
  Input operator()(const TriTriInput& in) const { return TriTriInput{flush(in.a), flush(in.b)}; }
  Input operator()(const MeshMeshInput& in) const { return in; }  // never scaled
  Input operator()(const MeshMeshFirstInput& in) const { return in; }
  Input operator()(const BroadphaseInput& in) const {
    BroadphaseInput r = in;
    for (auto& frame : r.frames) {
      for (auto& b : frame) {
        if (b) b = flush(*b);
      }
    }
    return r;
  }
  Input operator()(const RayMeshInput& in) const { return in; }  // never transformed
  Input operator()(const MovingObbInput& in) const {
    return MovingObbInput{{flush(in.a.box), flush(in.a.velocity)}, {flush(in.b.box), flush(in.b.velocity)}};
  }
};

}  // namespace

std::string_view to_string(Relation r) {
  switch (r) {
    case Relation::swap_shapes: return "swap shapes";
    case Relation::permute_axes: return "permute axes";
    case Relation::flip_axis: return "flip an axis";
    case Relation::scale: return "scale by 2^k";
    case Relation::permute_vertices: return "reorder vertices";
    case Relation::permute_faces: return "reorder faces";
    case Relation::permute_points: return "reorder points";
    case Relation::permute_objects: return "reorder objects";
  }
  return "?";
}

bool relation_applies(QueryKind kind, Relation relation) {
  const bool triangles = kind == QueryKind::tri_aabb || kind == QueryKind::tri_obb || kind == QueryKind::tri_tri;
  const bool meshes = is_mesh_query(kind) || kind == QueryKind::ray_mesh;
  switch (relation) {
    case Relation::permute_vertices: return triangles || meshes;
    case Relation::permute_faces: return meshes;
    case Relation::permute_points: return kind == QueryKind::kdop_kdop;
    case Relation::permute_objects: return kind == QueryKind::broadphase;
    default: break;
  }
  // A flip would make a pose an improper rotation; swapping the meshes transposes the pairs but
  // moves a into b's frame instead, with other roundings; scaling would copy the meshes.
  if (is_mesh_query(kind)) return relation == Relation::permute_axes;
  // A geometric ray_mesh relation would have to transform the mesh's coordinates; broadphase has
  // no two shapes.
  if (kind == QueryKind::ray_mesh) return false;
  if (kind == QueryKind::broadphase) return relation != Relation::swap_shapes;
  const bool two_shapes_alike = kind != QueryKind::ray_aabb && kind != QueryKind::tri_aabb && kind != QueryKind::tri_obb;
  return relation != Relation::swap_shapes || two_shapes_alike;
}

std::optional<Input> transform(const Input& input, Relation relation, int parameter) {
  if (!relation_applies(kind_of(input), relation)) return std::nullopt;
  Map map{relation, parameter};
  std::optional<Input> out = std::visit(map, input);
  if (!map.ok) return std::nullopt;
  return out;
}

Input flush_extremes(const Input& input) { return std::visit(Flush{}, input); }

Answer mapped_answer(const Answer& answer, const Input& original, Relation relation, int parameter) {
  Answer out = answer;
  const auto rename = [](std::vector<FacePair>& pairs, const auto& map) {
    for (FacePair& p : pairs) p = map(p);
    std::sort(pairs.begin(), pairs.end());
  };
  if (relation == Relation::permute_faces) {
    if (const MeshPair* m = meshes_of(original)) {
      const auto a = shuffle_of(m->a.mesh->size(), parameter, kSaltA), b = shuffle_of(m->b.mesh->size(), parameter, kSaltB);
      rename(out.pairs, [&](const FacePair& p) { return FacePair{a[p.first], b[p.second]}; });
    } else if (const auto* ray = std::get_if<RayMeshInput>(&original)) {
      const auto place = shuffle_of(ray->mesh.mesh->size(), parameter, kSaltA);
      rename(out.pairs, [&](const FacePair& p) { return FacePair{place[p.first], p.second}; });
    }
  }
  if (relation == Relation::permute_objects) {
    if (const auto* in = std::get_if<BroadphaseInput>(&original)) {
      const auto place = shuffle_of(in->frames.empty() ? 0 : in->frames[0].size(), parameter, kSaltA);
      for (auto& frame : out.frames) rename(frame, [&](const FacePair& p) { return std::minmax(place[p.first], place[p.second]); });
    }
  }
  return out;
}

}  // namespace cc::harness
