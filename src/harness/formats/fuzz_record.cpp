#include "harness/formats/fuzz_record.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "harness/generation/rotation.h"

namespace cc::harness {
namespace {

constexpr int kKs[] = {6, 14, 16, 18, 24, 26};
constexpr std::uint8_t kTminInfinite = 0x10, kTmaxInfinite = 0x20;

// Reads fields in order from the doubles of a record.
struct Reader {
  std::span<const double> values;
  std::size_t next = 0;
  double number() { return next < values.size() ? values[next++] : 0.0; }
  Vec3 vec3() {
    const double x = number(), y = number(), z = number();
    return {x, y, z};
  }
  Mat3 columns() {
    const Vec3 a = vec3(), b = vec3(), c = vec3();
    return Mat3::from_columns(a, b, c);
  }
  Triangle triangle() {
    const Vec3 a = vec3(), b = vec3(), c = vec3();
    return {{a, b, c}};
  }
  Obb obb() {
    const Vec3 c = vec3(), h = vec3();
    return {c, h, columns()};
  }
};

struct Writer {
  std::vector<double> values;
  void number(double x) { values.push_back(x); }
  void vec3(const Vec3& v) { number(v.x), number(v.y), number(v.z); }
  void triangle(const Triangle& t) { vec3(t.v[0]), vec3(t.v[1]), vec3(t.v[2]); }
  void obb(const Obb& b) { vec3(b.center), vec3(b.half), vec3(b.axes.col[0]), vec3(b.axes.col[1]), vec3(b.axes.col[2]); }
};

// Mesh queries: the header bytes after the tag.
struct MeshHeader {
  std::size_t triangles_a = 1, triangles_b = 1;  // 1 + byte % 4
  std::size_t rotation = 0;                      // pose_b's rotation: table_rotation(byte % 32)
  std::uint8_t library = 0;                      // bv, strategy, update, descent bits
};
constexpr std::size_t kMeshHeaderBytes = 4;
constexpr std::size_t kMaxSoup = 4;

LibraryBvh library_of(std::uint8_t bits) {
  LibraryBvh l;
  l.bv = kAllBvTypes[bits & 7];
  l.build.strategy = static_cast<BuildStrategy>(((bits >> 3) & 3) % 3);
  l.update = (bits & 0x20) ? BvUpdate::exact : BvUpdate::approximate;
  l.descent = (bits & 0x40) ? Descent::larger : Descent::first_model;
  return l;
}

std::uint8_t library_bits(const LibraryBvh& l) {
  std::uint8_t bits = 0;
  for (std::uint8_t i = 0; i < 8; ++i) bits = kAllBvTypes[i] == l.bv ? i : bits;
  bits |= static_cast<std::uint8_t>(static_cast<int>(l.build.strategy) << 3);
  if (l.update == BvUpdate::exact) bits |= 0x20;
  if (l.descent == Descent::larger) bits |= 0x40;
  return bits;
}

Mesh soup(Reader& r, std::size_t n);

MeshPair mesh_pair(const MeshHeader& h, Reader& r) {
  MeshPair m;
  m.pose_b.rotation = table_rotation(h.rotation);
  m.pose_b.translation = r.vec3();
  m.a = triangles_mesh(soup(r, h.triangles_a));
  m.b = triangles_mesh(soup(r, h.triangles_b));
  m.library = library_of(h.library);
  return m;
}

MeshHeader mesh_header_of(const MeshPair& m) {
  MeshHeader h;
  h.triangles_a = std::clamp<std::size_t>(m.a.mesh->size(), 1, kMaxSoup);
  h.triangles_b = std::clamp<std::size_t>(m.b.mesh->size(), 1, kMaxSoup);
  h.rotation = table_rotation_index(m.pose_b.rotation).value_or(0);
  h.library = library_bits(m.library);
  return h;
}

// broadphase: the header bytes after the tag.
constexpr std::size_t kMaxBoxes = 8, kMaxFrames = 4;
struct BroadphaseHeader {
  std::size_t boxes = 1, frames = 1;                      // 1 + byte % 8, 1 + byte % 4
  std::array<std::uint8_t, kMaxFrames> present{};         // bit i: box i is in that frame
};
constexpr std::size_t kBroadphaseHeaderBytes = 2 + kMaxFrames;

BroadphaseHeader broadphase_header_of(const BroadphaseInput& in) {
  BroadphaseHeader h;
  h.frames = std::clamp<std::size_t>(in.frames.size(), 1, kMaxFrames);
  h.boxes = std::clamp<std::size_t>(in.frames.empty() ? 1 : in.frames[0].size(), 1, kMaxBoxes);
  for (std::size_t f = 0; f < h.frames && f < in.frames.size(); ++f) {
    for (std::size_t i = 0; i < h.boxes && i < in.frames[f].size(); ++i) {
      if (in.frames[f][i]) h.present[f] |= static_cast<std::uint8_t>(1u << i);
    }
  }
  return h;
}

// ray_mesh: the header bytes after the tag.
struct RayMeshHeader {
  std::size_t triangles = 1;  // 1 + byte % 4
  std::uint8_t library = 0;
};
constexpr std::size_t kRayMeshHeaderBytes = 2;

// The shape of a record beyond its kind: k and point counts, mesh and broadphase headers.
struct Shape {
  int k = 18;
  std::size_t na = 0, nb = 0;
  MeshHeader mesh;
  BroadphaseHeader broadphase;
  RayMeshHeader ray_mesh;
};

Mesh soup(Reader& r, std::size_t n) {
  Mesh mesh;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Triangle t = r.triangle();
    mesh.vertices.insert(mesh.vertices.end(), t.v.begin(), t.v.end());
    mesh.faces.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  return mesh;
}

// The input of a given kind (and shape) made from record values.
Input build(QueryKind kind, const Shape& shape, std::uint8_t flags, std::span<const double> values) {
  const int k = shape.k;
  const std::size_t na = shape.na, nb = shape.nb;
  const MeshHeader& mesh = shape.mesh;
  Reader r{values};
  switch (kind) {
    case QueryKind::ray_aabb: {
      RayAabbInput in;
      in.ray.origin = r.vec3();
      in.ray.dir = r.vec3();
      in.ray.tmin = r.number();
      in.ray.tmax = r.number();
      in.box = {r.vec3(), r.vec3()};
      if (flags & kTminInfinite) in.ray.tmin = -INFINITY;
      if (flags & kTmaxInfinite) in.ray.tmax = INFINITY;
      return in;
    }
    case QueryKind::sphere_sphere: {
      SphereSphereInput in;
      in.a.center = r.vec3(), in.a.radius = r.number(), in.b.center = r.vec3(), in.b.radius = r.number();
      return in;
    }
    case QueryKind::aabb_aabb: {
      AabbAabbInput in;
      in.a = {r.vec3(), r.vec3()};
      in.b = {r.vec3(), r.vec3()};
      return in;
    }
    case QueryKind::kdop_kdop: {
      KdopKdopInput in;
      in.k = k;
      for (std::size_t i = 0; i < na; ++i) in.a.push_back(r.vec3());
      for (std::size_t i = 0; i < nb; ++i) in.b.push_back(r.vec3());
      return in;
    }
    case QueryKind::obb_obb: {
      ObbObbInput in;
      in.a = r.obb();
      in.b = r.obb();
      return in;
    }
    case QueryKind::tri_aabb: {
      TriAabbInput in;
      in.tri = r.triangle();
      in.box = {r.vec3(), r.vec3()};
      return in;
    }
    case QueryKind::tri_obb: {
      TriObbInput in;
      in.tri = r.triangle();
      in.box = r.obb();
      return in;
    }
    case QueryKind::tri_tri: {
      TriTriInput in;
      in.a = r.triangle();
      in.b = r.triangle();
      return in;
    }
    case QueryKind::mesh_mesh: return MeshMeshInput{mesh_pair(mesh, r)};
    case QueryKind::mesh_mesh_first: return MeshMeshFirstInput{mesh_pair(mesh, r)};
    case QueryKind::broadphase: {
      BroadphaseInput in;
      for (std::size_t f = 0; f < shape.broadphase.frames; ++f) {
        auto& frame = in.frames.emplace_back();
        for (std::size_t i = 0; i < shape.broadphase.boxes; ++i) {
          const Vec3 lo = r.vec3(), hi = r.vec3();
          frame.push_back(shape.broadphase.present[f] & (1u << i) ? std::optional(Aabb{lo, hi}) : std::nullopt);
        }
      }
      return in;
    }
    case QueryKind::ray_mesh: {
      RayMeshInput in;
      in.ray.origin = r.vec3();
      in.ray.dir = r.vec3();
      in.ray.tmin = r.number();
      in.ray.tmax = r.number();
      if (flags & kTminInfinite) in.ray.tmin = -INFINITY;
      if (flags & kTmaxInfinite) in.ray.tmax = INFINITY;
      in.mesh = triangles_mesh(soup(r, shape.ray_mesh.triangles));
      in.library = library_of(shape.ray_mesh.library);
      return in;
    }
    case QueryKind::moving_obb: {
      MovingObbInput in;
      in.a.box = r.obb();
      in.a.velocity = r.vec3();
      in.b.box = r.obb();
      in.b.velocity = r.vec3();
      return in;
    }
  }
  return {};
}

struct Values {
  Writer w;
  void operator()(const RayAabbInput& in) {
    w.vec3(in.ray.origin), w.vec3(in.ray.dir), w.number(in.ray.tmin), w.number(in.ray.tmax), w.vec3(in.box.lo),
        w.vec3(in.box.hi);
  }
  void operator()(const SphereSphereInput& in) {
    w.vec3(in.a.center), w.number(in.a.radius), w.vec3(in.b.center), w.number(in.b.radius);
  }
  void operator()(const AabbAabbInput& in) { w.vec3(in.a.lo), w.vec3(in.a.hi), w.vec3(in.b.lo), w.vec3(in.b.hi); }
  void operator()(const KdopKdopInput& in) {
    for (const Vec3& p : in.a) w.vec3(p);
    for (const Vec3& p : in.b) w.vec3(p);
  }
  void operator()(const ObbObbInput& in) { w.obb(in.a), w.obb(in.b); }
  void operator()(const TriAabbInput& in) { w.triangle(in.tri), w.vec3(in.box.lo), w.vec3(in.box.hi); }
  void operator()(const TriObbInput& in) { w.triangle(in.tri), w.obb(in.box); }
  void operator()(const TriTriInput& in) { w.triangle(in.a), w.triangle(in.b); }
  void operator()(const MeshMeshInput& in) { meshes(in.meshes); }
  void operator()(const MeshMeshFirstInput& in) { meshes(in.meshes); }
  void operator()(const BroadphaseInput& in) {
    const BroadphaseHeader h = broadphase_header_of(in);
    for (std::size_t f = 0; f < h.frames; ++f) {
      for (std::size_t i = 0; i < h.boxes; ++i) {
        const bool present = f < in.frames.size() && i < in.frames[f].size() && in.frames[f][i];
        const Aabb box = present ? *in.frames[f][i] : Aabb{};
        w.vec3(box.lo), w.vec3(box.hi);
      }
    }
  }
  void operator()(const RayMeshInput& in) {
    w.vec3(in.ray.origin), w.vec3(in.ray.dir), w.number(in.ray.tmin), w.number(in.ray.tmax);
    soup(*in.mesh.mesh);
  }
  void operator()(const MovingObbInput& in) {
    w.obb(in.a.box), w.vec3(in.a.velocity), w.obb(in.b.box), w.vec3(in.b.velocity);
  }
  void soup(const Mesh& mesh) {
    const std::size_t n = std::clamp<std::size_t>(mesh.size(), 1, kMaxSoup);
    for (std::size_t i = 0; i < n; ++i) w.triangle(i < mesh.size() ? mesh.triangle(i) : Triangle{});
  }
  void meshes(const MeshPair& m) {
    w.vec3(m.pose_b.translation);
    for (const MeshRef* r : {&m.a, &m.b}) soup(*r->mesh);
  }
};

int k_index(int k) {
  for (int i = 0; i < 6; ++i) {
    if (kKs[i] == k) return i;
  }
  return 3;
}

}  // namespace

std::vector<double> record_values(const Input& input) {
  Values v;
  std::visit(v, input);
  return v.w.values;
}

namespace {

Shape shape_of(const Input& input) {
  Shape s;
  if (const auto* kd = std::get_if<KdopKdopInput>(&input)) s.k = kd->k, s.na = kd->a.size(), s.nb = kd->b.size();
  if (const MeshPair* m = meshes_of(input)) s.mesh = mesh_header_of(*m);
  if (const auto* b = std::get_if<BroadphaseInput>(&input)) s.broadphase = broadphase_header_of(*b);
  if (const auto* rm = std::get_if<RayMeshInput>(&input)) {
    s.ray_mesh.triangles = std::clamp<std::size_t>(rm->mesh.mesh->size(), 1, kMaxSoup);
    s.ray_mesh.library = library_bits(rm->library);
  }
  return s;
}

}  // namespace

Input with_record_values(const Input& shape, std::span<const double> values) {
  return build(kind_of(shape), shape_of(shape), 0, values);  // ray ends are values
}

std::vector<std::uint8_t> encode_record(const Input& input) {
  const QueryKind kind = kind_of(input);
  std::vector<std::uint8_t> bytes;
  std::uint8_t tag = static_cast<std::uint8_t>(kind);
  const Ray* ray = nullptr;
  if (const auto* in = std::get_if<RayAabbInput>(&input)) ray = &in->ray;
  if (const auto* in = std::get_if<RayMeshInput>(&input)) ray = &in->ray;
  if (ray != nullptr) {
    if (ray->tmin == -INFINITY) tag |= kTminInfinite;
    if (ray->tmax == INFINITY) tag |= kTmaxInfinite;
  }
  bytes.push_back(tag);
  if (const auto* kd = std::get_if<KdopKdopInput>(&input)) {
    bytes.push_back(static_cast<std::uint8_t>(k_index(kd->k)));
    bytes.push_back(static_cast<std::uint8_t>(kd->a.empty() ? 0 : (kd->a.size() - 1) % 8));
    bytes.push_back(static_cast<std::uint8_t>(kd->b.empty() ? 0 : (kd->b.size() - 1) % 8));
  }
  if (const MeshPair* m = meshes_of(input)) {
    const MeshHeader h = mesh_header_of(*m);
    bytes.insert(bytes.end(), {static_cast<std::uint8_t>(h.triangles_a - 1), static_cast<std::uint8_t>(h.triangles_b - 1),
                               static_cast<std::uint8_t>(h.rotation), h.library});
  }
  const Shape shape = shape_of(input);
  if (kind == QueryKind::broadphase) {
    bytes.push_back(static_cast<std::uint8_t>(shape.broadphase.boxes - 1));
    bytes.push_back(static_cast<std::uint8_t>(shape.broadphase.frames - 1));
    bytes.insert(bytes.end(), shape.broadphase.present.begin(), shape.broadphase.present.end());
  }
  if (kind == QueryKind::ray_mesh) {
    bytes.push_back(static_cast<std::uint8_t>(shape.ray_mesh.triangles - 1));
    bytes.push_back(shape.ray_mesh.library);
  }
  for (double x : record_values(input)) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    for (int i = 0; i < 8; ++i) bytes.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
  }
  return bytes;
}

Input decode_record(QueryKind kind, std::span<const std::uint8_t> bytes) {
  const auto byte = [&bytes](std::size_t i) -> std::uint8_t { return i < bytes.size() ? bytes[i] : 0; };
  const std::uint8_t flags = byte(0) & 0xf0;
  std::size_t offset = 1;
  Shape shape;
  int& k = shape.k;
  std::size_t &na = shape.na, &nb = shape.nb, count = 0;
  MeshHeader& mesh = shape.mesh;
  switch (kind) {
    case QueryKind::ray_aabb: count = 14; break;
    case QueryKind::sphere_sphere: count = 8; break;
    case QueryKind::aabb_aabb: count = 12; break;
    case QueryKind::kdop_kdop:
      k = kKs[byte(1) % 6];
      na = 1 + byte(2) % 8;
      nb = 1 + byte(3) % 8;
      offset = 4;
      count = 3 * (na + nb);
      break;
    case QueryKind::obb_obb: count = 30; break;
    case QueryKind::tri_aabb: count = 15; break;
    case QueryKind::tri_obb: count = 24; break;
    case QueryKind::tri_tri: count = 18; break;
    case QueryKind::mesh_mesh:
    case QueryKind::mesh_mesh_first:
      mesh.triangles_a = 1 + byte(1) % kMaxSoup;
      mesh.triangles_b = 1 + byte(2) % kMaxSoup;
      mesh.rotation = byte(3) % 32;
      mesh.library = byte(4);
      offset = 1 + kMeshHeaderBytes;
      count = 3 + 9 * (mesh.triangles_a + mesh.triangles_b);
      break;
    case QueryKind::broadphase:
      shape.broadphase.boxes = 1 + byte(1) % kMaxBoxes;
      shape.broadphase.frames = 1 + byte(2) % kMaxFrames;
      for (std::size_t f = 0; f < kMaxFrames; ++f) shape.broadphase.present[f] = byte(3 + f);
      offset = 1 + kBroadphaseHeaderBytes;
      count = 6 * shape.broadphase.boxes * shape.broadphase.frames;
      break;
    case QueryKind::ray_mesh:
      shape.ray_mesh.triangles = 1 + byte(1) % kMaxSoup;
      shape.ray_mesh.library = byte(2);
      offset = 1 + kRayMeshHeaderBytes;
      count = 8 + 9 * shape.ray_mesh.triangles;
      break;
    case QueryKind::moving_obb: count = 36; break;
  }
  std::vector<double> values(count, 0.0);
  for (std::size_t i = 0; i < count; ++i) {
    std::uint64_t bits = 0;
    for (int b = 0; b < 8; ++b) bits |= static_cast<std::uint64_t>(byte(offset + 8 * i + static_cast<std::size_t>(b))) << (8 * b);
    std::memcpy(&values[i], &bits, sizeof bits);
  }
  return build(kind, shape, flags, values);
}

}  // namespace cc::harness
