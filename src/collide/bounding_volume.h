// What a bounding-volume hierarchy needs of its bounding volume: one traits class per type
// (Aabb, Obb, Kdop<K>, Sphere), so that building and traversal are written once.
#pragma once

#include <span>
#include <string>

#include "collide/aabb.h"
#include "collide/kdop.h"
#include "collide/obb.h"
#include "collide/obb_fit.h"
#include "collide/sphere_fit.h"

namespace cc {

/// A bounding volume's size, for the building heuristics: volume first, surface area to rank
/// flat volumes (whose volume is 0 or nearly so).
struct BvSize {
  double volume = 0, area = 0;
  friend BvSize operator+(BvSize a, BvSize b) { return {a.volume + b.volume, a.area + b.area}; }
  friend BvSize operator-(BvSize a, BvSize b) { return {a.volume - b.volume, a.area - b.area}; }
  friend bool operator<(BvSize a, BvSize b) { return a.volume != b.volume ? a.volume < b.volume : a.area < b.area; }
};

/// The size of the box with these half extents.
inline BvSize box_size(const Vec3& half) {
  return {8 * half.x * half.y * half.z, 8 * (half.x * half.y + half.y * half.z + half.z * half.x)};
}

/// BoundingVolume<BV> provides, for BV in {Aabb, Obb, Kdop<K>, Sphere}:
///  - name():            "AABB", "OBB", "k-DOP<K>" or "sphere";
///  - fit(points):       a volume that contains every point in exact arithmetic;
///  - merge(a, b):       a volume that contains both (the smallest for Aabb and k-DOPs);
///  - overlap(a, b):     the library's conservative overlap test;
///  - axes(v), center(v), half(v): a frame of the volume for splitting (the coordinate axes for
///                       Aabb, k-DOPs and spheres, the box's own for Obb) and its extent along it;
///  - size(v):           the BvSize of that box (for a k-DOP, of its x, y, z slabs; for a sphere,
///                       of the cube around it).
template <class BV>
struct BoundingVolume;

template <>
struct BoundingVolume<Aabb> {
  static std::string name() { return "AABB"; }
  static Aabb fit(std::span<const Vec3> points) {
    Aabb box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    for (const Vec3& p : points) {
      for (int i = 0; i < 3; ++i) box.lo[i] = std::min(box.lo[i], p[i]), box.hi[i] = std::max(box.hi[i], p[i]);
    }
    return box;
  }
  static Aabb merge(const Aabb& a, const Aabb& b) {
    Aabb m;
    for (int i = 0; i < 3; ++i) m.lo[i] = std::min(a.lo[i], b.lo[i]), m.hi[i] = std::max(a.hi[i], b.hi[i]);
    return m;
  }
  static bool overlap(const Aabb& a, const Aabb& b) { return test_aabb_aabb(a, b); }
  static Mat3 axes(const Aabb&) { return Mat3::identity(); }
  static Vec3 center(const Aabb& b) { return 0.5 * (b.lo + b.hi); }
  static Vec3 half(const Aabb& b) { return 0.5 * (b.hi - b.lo); }
  [[gnu::always_inline]] static BvSize size(const Aabb& b) { return box_size(half(b)); }
};

template <>
struct BoundingVolume<Obb> {
  static std::string name() { return "OBB"; }
  static Obb fit(std::span<const Vec3> points) { return fit_obb(points); }
  /// merge_obbs: the box with the axes of the larger of the two that holds both; cheap, for
  /// the building heuristics (the hierarchy's own boxes are fitted to the triangles).
  static Obb merge(const Obb& a, const Obb& b) { return merge_obbs(a, b, size(b) < size(a) ? a.axes : b.axes); }
  static bool overlap(const Obb& a, const Obb& b) { return test_obb_obb(a, b); }
  static Mat3 axes(const Obb& b) { return b.axes; }
  static Vec3 center(const Obb& b) { return b.center; }
  static Vec3 half(const Obb& b) { return b.half; }
  static BvSize size(const Obb& b) { return box_size(b.half); }
};

template <int K>
struct BoundingVolume<Kdop<K>> {
  static std::string name() { return "k-DOP<" + std::to_string(K) + ">"; }
  static Kdop<K> fit(std::span<const Vec3> points) { return fit_kdop<K>(points); }
  static Kdop<K> merge(const Kdop<K>& a, const Kdop<K>& b) {
    Kdop<K> m;
    for (int i = 0; i < K / 2; ++i) m.lo[i] = std::min(a.lo[i], b.lo[i]), m.hi[i] = std::max(a.hi[i], b.hi[i]);
    return m;
  }
  static bool overlap(const Kdop<K>& a, const Kdop<K>& b) { return test_kdop_kdop(a, b); }
  static Mat3 axes(const Kdop<K>&) { return Mat3::identity(); }
  static Vec3 center(const Kdop<K>& d) { return {0.5 * (d.lo[0] + d.hi[0]), 0.5 * (d.lo[1] + d.hi[1]), 0.5 * (d.lo[2] + d.hi[2])}; }
  static Vec3 half(const Kdop<K>& d) { return {0.5 * (d.hi[0] - d.lo[0]), 0.5 * (d.hi[1] - d.lo[1]), 0.5 * (d.hi[2] - d.lo[2])}; }
  [[gnu::always_inline]] static BvSize size(const Kdop<K>& d) { return box_size(half(d)); }
};

/// Spheres: the notes' first bounding volume, which a rotation leaves as it is.
template <>
struct BoundingVolume<Sphere> {
  static std::string name() { return "sphere"; }
  static Sphere fit(std::span<const Vec3> points) { return fit_sphere(points); }
  static Sphere merge(const Sphere& a, const Sphere& b) { return merge_spheres(a, b); }
  static bool overlap(const Sphere& a, const Sphere& b) { return test_sphere_sphere(a, b); }
  static Mat3 axes(const Sphere&) { return Mat3::identity(); }
  static Vec3 center(const Sphere& s) { return s.center; }
  static Vec3 half(const Sphere& s) { return {s.radius, s.radius, s.radius}; }
  [[gnu::always_inline]] static BvSize size(const Sphere& s) { return box_size(half(s)); }
};

}  // namespace cc

/// Applies X to every volume type the hierarchies take (for their explicit instantiations).
#define CC_FOR_EACH_BOUNDING_VOLUME(X) \
  X(cc::Aabb) X(cc::Obb) X(cc::Kdop<6>) X(cc::Kdop<14>) X(cc::Kdop<16>) X(cc::Kdop<18>) X(cc::Kdop<24>) X(cc::Kdop<26>) \
  X(cc::Sphere)
