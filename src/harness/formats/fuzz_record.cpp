#include "harness/formats/fuzz_record.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>

#include "harness/model/parts.h"
#include "harness/generation/rotation.h"

namespace cc::harness {
namespace {

constexpr int kKs[] = {6, 14, 16, 18, 24, 26};
constexpr std::uint8_t kTminInfinite = 0x10, kTmaxInfinite = 0x20;
constexpr std::size_t kMaxPoints = 8, kMaxSoup = 4, kMaxBoxes = 8, kMaxFrames = 4, kMaxParts = 8;

// The index of a rotation in table_rotation's table, if it is one of them.
std::optional<std::size_t> table_rotation_index(const Mat3& m) {
  for (std::size_t i = 0; i < 32; ++i) {
    if (table_rotation(i) == m) return i;
  }
  return std::nullopt;
}

// A record being written: the tag's flags, the header bytes, the values.
struct Writer {
  std::uint8_t flags = 0;
  std::vector<std::uint8_t> header;
  std::vector<double> values;
  void byte(std::size_t b) { header.push_back(static_cast<std::uint8_t>(b)); }
  void number(double x) { values.push_back(x); }
};

// A record being read: the header bytes in order from just after the tag, the values in order
// from just after the header (a short record reads as if padded with zero bytes).
struct Reader {
  std::span<const std::uint8_t> bytes;
  std::uint8_t flags = 0;
  std::size_t next_byte = 1;
  std::size_t next_value = 0;  // the offset of the first value once the header's size is known

  std::uint8_t at(std::size_t i) const { return i < bytes.size() ? bytes[i] : 0; }
  std::uint8_t byte() { return at(next_byte++); }
  double number() {
    std::uint64_t bits = 0;
    for (std::size_t b = 0; b < 8; ++b) bits |= static_cast<std::uint64_t>(at(next_value + b)) << (8 * b);
    next_value += 8;
    double x = 0;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }
};

// The header bytes each part takes.
template <class T, class As = Plain>
constexpr std::size_t header_bytes();

// --- leaves -------------------------------------------------------------------------------

void write(Writer& w, double x, Plain) { w.number(x); }
void read(Reader& r, double& x, Plain) { x = r.number(); }
void write(Writer& w, const Vec3& v, Plain) { w.number(v.x), w.number(v.y), w.number(v.z); }
void read(Reader& r, Vec3& v, Plain) {
  const double x = r.number(), y = r.number(), z = r.number();
  v = {x, y, z};
}
void write(Writer& w, const Vec2& v, Plain) { w.number(v.x), w.number(v.y); }
void read(Reader& r, Vec2& v, Plain) {
  const double x = r.number(), y = r.number();
  v = {x, y};
}
void write(Writer& w, const Mat3& m, AsFrame) { write(w, m.col[0], Plain{}), write(w, m.col[1], Plain{}), write(w, m.col[2], Plain{}); }
void read(Reader& r, Mat3& m, AsFrame) {
  for (Vec3& column : m.col) read(r, column, Plain{});
}
void write(Writer& w, const Triangle& t, Plain) { write(w, t.v[0], Plain{}), write(w, t.v[1], Plain{}), write(w, t.v[2], Plain{}); }
void read(Reader& r, Triangle& t, Plain) {
  for (Vec3& p : t.v) read(r, p, Plain{});
}

// k: a byte, an index into kKs (modulo 6).
int k_index(int k) {
  for (int i = 0; i < 6; ++i) {
    if (kKs[i] == k) return i;
  }
  return 3;
}
void write(Writer& w, int k, AsKdopK) { w.byte(static_cast<std::size_t>(k_index(k))); }
void read(Reader& r, int& k, AsKdopK) { k = kKs[r.byte() % 6]; }

// A point set: a byte (1 + b % 8 points), then the points.
void write(Writer& w, const std::vector<Vec3>& points, Plain) {
  w.byte(points.empty() ? 0 : (points.size() - 1) % kMaxPoints);
  for (const Vec3& p : points) write(w, p, Plain{});
}
void read(Reader& r, std::vector<Vec3>& points, Plain) {
  points.resize(1 + r.byte() % kMaxPoints);
  for (Vec3& p : points) read(r, p, Plain{});
}

// A mesh as a soup of 1 to 4 triangles: a byte (1 + b % 4 triangles), then their vertices.
std::size_t soup_size(const Mesh& mesh) { return std::clamp<std::size_t>(mesh.size(), 1, kMaxSoup); }
void write_soup(Writer& w, const Mesh& mesh) {
  for (std::size_t i = 0; i < soup_size(mesh); ++i) write(w, i < mesh.size() ? mesh.triangle(i) : Triangle{}, Plain{});
}
MeshRef read_soup(Reader& r, std::size_t n) {
  Mesh mesh;
  for (std::uint32_t i = 0; i < n; ++i) {
    Triangle t;
    read(r, t, Plain{});
    mesh.vertices.insert(mesh.vertices.end(), t.v.begin(), t.v.end());
    mesh.faces.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  return triangles_mesh(std::move(mesh));
}
void write(Writer& w, const MeshRef& m, Plain) {
  w.byte(soup_size(*m.mesh) - 1);
  write_soup(w, *m.mesh);
}
void read(Reader& r, MeshRef& m, Plain) { m = read_soup(r, 1 + r.byte() % kMaxSoup); }

// The library's hierarchy: a byte (bits 0-2 the volume among the first eight of kAllBvTypes, 3-4
// the build strategy, 5 the exact update, 6 the larger-first descent, 7 a sphere tree, bits
// 0-2 then unused); the other build options are the defaults. The hill-climbing update is
// written as the exact update, whose volumes it finds.
void write(Writer& w, const LibraryBvh& l, Plain) {
  std::size_t bits = l.bv == BvType::sphere ? 0x80 : 0;
  for (std::size_t i = 0; i < 8; ++i) bits |= kAllBvTypes[i] == l.bv ? i : 0;
  bits |= static_cast<std::size_t>(l.build.strategy) << 3;
  if (l.update != BvUpdate::approximate) bits |= 0x20;
  if (l.descent == Descent::larger) bits |= 0x40;
  w.byte(bits);
}
void read(Reader& r, LibraryBvh& l, Plain) {
  const std::uint8_t bits = r.byte();
  l = {};
  l.bv = (bits & 0x80) ? BvType::sphere : kAllBvTypes[bits & 7];
  l.build.strategy = static_cast<BuildStrategy>((bits >> 3) & 3);
  l.update = (bits & 0x20) ? BvUpdate::exact : BvUpdate::approximate;
  l.descent = (bits & 0x40) ? Descent::larger : Descent::first_model;
}

// A ray: its fields, and the tag's flags for infinite ends (bit 4: tmin = -inf, bit 5: tmax = +inf).
void write(Writer& w, const Ray& ray, Plain) {
  write(w, ray.origin, Plain{}), write(w, ray.dir, Plain{}), w.number(ray.tmin), w.number(ray.tmax);
  if (ray.tmin == -INFINITY) w.flags |= kTminInfinite;
  if (ray.tmax == INFINITY) w.flags |= kTmaxInfinite;
}
void read(Reader& r, Ray& ray, Plain) {
  read(r, ray.origin, Plain{}), read(r, ray.dir, Plain{}), read(r, ray.tmin, Plain{}), read(r, ray.tmax, Plain{});
  if (r.flags & kTminInfinite) ray.tmin = -INFINITY;
  if (r.flags & kTmaxInfinite) ray.tmax = INFINITY;
}

// Two placed meshes: four bytes (triangles of a, of b, b's rotation by its index in
// table_rotation(b % 32), the hierarchy), then b's translation and the soups of a and b; a's
// pose is the identity (a rotation not in the table is recorded as the identity).
void write(Writer& w, const MeshPair& m, Plain) {
  w.byte(soup_size(*m.a.mesh) - 1);
  w.byte(soup_size(*m.b.mesh) - 1);
  w.byte(table_rotation_index(m.pose_b.rotation).value_or(0));
  write(w, m.library, Plain{});
  write(w, m.pose_b.translation, Plain{});
  write_soup(w, *m.a.mesh);
  write_soup(w, *m.b.mesh);
}
void read(Reader& r, MeshPair& m, Plain) {
  const std::size_t triangles_a = 1 + r.byte() % kMaxSoup, triangles_b = 1 + r.byte() % kMaxSoup;
  m = {};
  m.pose_b.rotation = table_rotation(r.byte() % 32);
  read(r, m.library, Plain{});
  read(r, m.pose_b.translation, Plain{});
  m.a = read_soup(r, triangles_a);
  m.b = read_soup(r, triangles_b);
}

// Boxes over frames: six bytes (1 + b % 8 boxes, 1 + b % 4 frames, then per frame a mask of
// the boxes present: bit i, box i), then lo and hi of every box of every frame (absent ones too,
// read and ignored).
void write(Writer& w, const BoxFrames& frames, Plain) {
  const std::size_t n_frames = std::clamp<std::size_t>(frames.size(), 1, kMaxFrames);
  const std::size_t n_boxes = std::clamp<std::size_t>(frames.empty() ? 1 : frames[0].size(), 1, kMaxBoxes);
  std::array<std::uint8_t, kMaxFrames> present{};
  for (std::size_t f = 0; f < n_frames && f < frames.size(); ++f) {
    for (std::size_t i = 0; i < n_boxes && i < frames[f].size(); ++i) {
      if (frames[f][i]) present[f] |= static_cast<std::uint8_t>(1u << i);
    }
  }
  w.byte(n_boxes - 1);
  w.byte(n_frames - 1);
  for (std::uint8_t mask : present) w.byte(mask);
  for (std::size_t f = 0; f < n_frames; ++f) {
    for (std::size_t i = 0; i < n_boxes; ++i) {
      const bool there = f < frames.size() && i < frames[f].size() && frames[f][i];
      const Aabb box = there ? *frames[f][i] : Aabb{};
      write(w, box.lo, Plain{}), write(w, box.hi, Plain{});
    }
  }
}
void read(Reader& r, BoxFrames& frames, Plain) {
  const std::size_t n_boxes = 1 + r.byte() % kMaxBoxes, n_frames = 1 + r.byte() % kMaxFrames;
  std::array<std::uint8_t, kMaxFrames> present{};
  for (std::uint8_t& mask : present) mask = r.byte();
  frames.clear();
  for (std::size_t f = 0; f < n_frames; ++f) {
    auto& frame = frames.emplace_back();
    for (std::size_t i = 0; i < n_boxes; ++i) {
      Aabb box;
      read(r, box.lo, Plain{}), read(r, box.hi, Plain{});
      frame.push_back(present[f] & (1u << i) ? std::optional(box) : std::nullopt);
    }
  }
}

// --- parts made of fields, in the order of their fields ------------------------------------

template <HasFields T>
void write(Writer& w, const T& value, Plain);
template <HasFields T>
void read(Reader& r, T& value, Plain);

// A list of parts: a byte (1 + b % 8 parts), then each part's values (the first 8 of a longer
// list; an empty list is written as one default part). A part of a list has no header bytes.
template <PartList L>
void write(Writer& w, const L& parts, Plain) {
  static_assert(header_bytes<typename L::value_type>() == 0, "a part of a list has no header bytes");
  const std::size_t n = std::clamp<std::size_t>(parts.size(), 1, kMaxParts);
  w.byte(n - 1);
  for (std::size_t i = 0; i < n; ++i) write(w, i < parts.size() ? parts[i] : typename L::value_type{}, Plain{});
}
template <PartList L>
void read(Reader& r, L& parts, Plain) {
  parts.resize(1 + r.byte() % kMaxParts);
  for (auto& part : parts) read(r, part, Plain{});
}

template <HasFields T>
void write(Writer& w, const T& value, Plain) {
  for_each_field<T>([&](const auto& f) {
    using F = std::decay_t<decltype(f)>;
    write(w, F::of(value), typename F::As{});
  });
}
template <HasFields T>
void read(Reader& r, T& value, Plain) {
  for_each_field<T>([&](const auto& f) {
    using F = std::decay_t<decltype(f)>;
    read(r, F::of(value), typename F::As{});
  });
}

template <class T, class As>
constexpr std::size_t header_bytes() {
  if constexpr (std::is_same_v<T, MeshPair>) {
    return 4;
  } else if constexpr (std::is_same_v<T, BoxFrames>) {
    return 2 + kMaxFrames;
  } else if constexpr (std::is_same_v<T, std::vector<Vec3>> || std::is_same_v<T, MeshRef> ||
                       std::is_same_v<T, LibraryBvh> || std::is_same_v<As, AsKdopK> || PartList<T>) {
    return 1;
  } else if constexpr (HasFields<T>) {
    std::size_t n = 0;
    for_each_field<T>([&n](const auto& f) {
      using F = std::decay_t<decltype(f)>;
      n += header_bytes<typename F::Type, typename F::As>();
    });
    return n;
  } else {
    return 0;
  }
}

}  // namespace

std::vector<std::uint8_t> encode_record(const Input& input) {
  Writer w;
  std::visit([&w](const auto& in) { write(w, in, Plain{}); }, input);
  std::vector<std::uint8_t> bytes;
  bytes.reserve(1 + w.header.size() + 8 * w.values.size());
  bytes.push_back(static_cast<std::uint8_t>(static_cast<std::uint8_t>(kind_of(input)) | w.flags));
  for (std::uint8_t b : w.header) bytes.push_back(b);
  for (double x : w.values) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    for (int i = 0; i < 8; ++i) bytes.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
  }
  return bytes;
}

Input decode_record(QueryKind kind, std::span<const std::uint8_t> bytes) {
  return with_kind(kind, [&]<class In>() -> Input {
    Reader r{bytes, static_cast<std::uint8_t>((bytes.empty() ? 0 : bytes[0]) & 0xf0)};
    r.next_value = 1 + header_bytes<In, Plain>();
    In in{};
    read(r, in, Plain{});
    return in;
  });
}

std::vector<double> record_values(const Input& input) {
  Writer w;
  std::visit([&w](const auto& in) { write(w, in, Plain{}); }, input);
  return w.values;
}

Input with_record_values(const Input& shape, std::span<const double> values) {
  std::vector<std::uint8_t> bytes = encode_record(shape);
  const std::size_t header = bytes.size() - 8 * record_values(shape).size();
  bytes.resize(header);
  bytes[0] &= 0x0f;  // the ray's ends are values here, not flags
  for (double x : values) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    for (int i = 0; i < 8; ++i) bytes.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
  }
  return decode_record(kind_of(shape), bytes);
}

}  // namespace cc::harness
