#include "harness/metamorphic.h"

#include <cmath>
#include <utility>

namespace cc::harness {
namespace {

constexpr int kPermutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

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
      case Relation::swap_shapes: return p;
    }
    return p;
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
    return TriAabbInput{triangle(in.tri), box(in.box)};
  }
  std::optional<Input> operator()(const TriObbInput& in) {
    return TriObbInput{triangle(in.tri), obb(in.box)};
  }
  std::optional<Input> operator()(const TriTriInput& in) {
    if (relation == Relation::swap_shapes) return TriTriInput{in.b, in.a};
    return TriTriInput{triangle(in.a), triangle(in.b)};
  }
  std::optional<Input> operator()(const BroadphaseInput& in) {
    BroadphaseInput r = in;
    for (auto& frame : r.frames) {
      for (auto& b : frame) {
        if (b) b = box(*b);
      }
    }
    return r;
  }
  std::optional<Input> operator()(const RayMeshInput&) { return std::nullopt; }
  std::optional<Input> operator()(const MovingObbInput& in) {
    if (relation == Relation::swap_shapes) return MovingObbInput{in.b, in.a};
    return MovingObbInput{{obb(in.a.box), point(in.a.velocity)}, {obb(in.b.box), point(in.b.velocity)}};
  }
  // Meshes: the world's axes permuted (the only relation that applies to them), which permutes
  // the rows of both poses; the relative transform, and with it every computation of the
  // library, is unchanged bit for bit.
  std::optional<Input> operator()(const MeshMeshInput& in) { return meshes(in.meshes, MeshMeshInput{}); }
  std::optional<Input> operator()(const MeshMeshFirstInput& in) { return meshes(in.meshes, MeshMeshFirstInput{}); }
  template <class Query>
  std::optional<Input> meshes(const MeshPair& m, Query out) {
    out.meshes = m;
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
  }
  return "?";
}

bool relation_applies(QueryKind kind, Relation relation) {
  // A flip would make a pose an improper rotation; swapping the meshes transposes the pairs but
  // moves a into b's frame instead, with other roundings; scaling would copy the meshes.
  if (is_mesh_query(kind)) return relation == Relation::permute_axes;
  // A ray_mesh relation would have to copy and transform the mesh; broadphase has no two shapes.
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

}  // namespace cc::harness
