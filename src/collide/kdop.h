// Discrete oriented polytopes (k-DOPs): the intersection of k/2 slabs whose normals come from a
// fixed direction set. AABB is the 6-DOP.
#pragma once

#include <array>
#include <limits>
#include <span>

#include "collide/vec3.h"

namespace cc {

/// A slab normal of a k-DOP: integer components in {-1, 0, 1}, not normalised.
struct KdopDirection {
  int x, y, z;
};

/// The direction sets, one slab per direction.
///  - k = 6, 14, 18, 26 follow Klosowski et al. (1998): the axes; the axes and the 4 diagonals;
///    the axes and the 6 edge directions; all 13.
///  - k = 16, 18, 24 follow FCL's KDOP<N> in FCL's order (its 18 is the same set as
///    Klosowski's), so that slab i is FCL's dist(i) and dist(i + N/2).
/// Closure (what the metamorphic tests may assume): 6, 14, 18, 26 are closed under permuting
/// and under flipping the axes; 24 only under permuting; 16 under neither.
namespace kdop_sets {
inline constexpr KdopDirection x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
inline constexpr std::array<KdopDirection, 3> k6 = {x, y, z};
inline constexpr std::array<KdopDirection, 7> k14 = {x, y, z, {1, 1, 1}, {1, -1, 1}, {1, 1, -1}, {1, -1, -1}};
inline constexpr std::array<KdopDirection, 8> k16 = {x, y, z, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, -1, 0}, {1, 0, -1}};
inline constexpr std::array<KdopDirection, 9> k18 = {x,         y,          z,          {1, 1, 0}, {1, 0, 1},
                                                      {0, 1, 1}, {1, -1, 0}, {1, 0, -1}, {0, 1, -1}};
inline constexpr std::array<KdopDirection, 12> k24 = {x,          y,          z,          {1, 1, 0},
                                                       {1, 0, 1},  {0, 1, 1},  {1, -1, 0}, {1, 0, -1},
                                                       {0, 1, -1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
inline constexpr std::array<KdopDirection, 13> k26 = {x,          y,          z,          {1, 1, 0},  {1, 0, 1},
                                                       {0, 1, 1},  {1, -1, 0}, {1, 0, -1}, {0, 1, -1}, {1, 1, 1},
                                                       {1, -1, 1}, {1, 1, -1}, {1, -1, -1}};
}  // namespace kdop_sets

template <int K>
constexpr std::span<const KdopDirection> kdop_directions() {
  static_assert(K == 6 || K == 14 || K == 16 || K == 18 || K == 24 || K == 26, "no such direction set");
  if constexpr (K == 6) return kdop_sets::k6;
  if constexpr (K == 14) return kdop_sets::k14;
  if constexpr (K == 16) return kdop_sets::k16;
  if constexpr (K == 18) return kdop_sets::k18;
  if constexpr (K == 24) return kdop_sets::k24;
  if constexpr (K == 26) return kdop_sets::k26;
}

/// The direction set for a k known only at run time; empty for an unsupported k.
constexpr std::span<const KdopDirection> kdop_directions(int k) {
  switch (k) {
    case 6: return kdop_directions<6>();
    case 14: return kdop_directions<14>();
    case 16: return kdop_directions<16>();
    case 18: return kdop_directions<18>();
    case 24: return kdop_directions<24>();
    case 26: return kdop_directions<26>();
  }
  return {};
}

/// True for the k for which a direction set exists: 6, 14, 16, 18, 24, 26.
constexpr bool is_supported_kdop(int k) { return k == 6 || k == 14 || k == 16 || k == 18 || k == 24 || k == 26; }

/// A k-DOP: slab i is [lo[i], hi[i]] along kdop_directions<K>()[i]. Default-constructed it is
/// empty (lo = +inf, hi = -inf) and overlaps nothing.
template <int K>
struct Kdop {
  static constexpr int kSlabs = K / 2;
  std::array<double, K / 2> lo;
  std::array<double, K / 2> hi;

  Kdop() {
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
  }
  friend bool operator==(const Kdop&, const Kdop&) = default;
};

/// The smallest k-DOP of the points, rounded outward: every input point lies inside the
/// returned k-DOP in exact arithmetic. Projections onto the axis directions are exact; those
/// onto 2- and 3-term directions are widened by 4u of their magnitude (|p.x|+|p.y|+|p.z|).
///  - No points: the empty k-DOP.
///  - A NaN or infinite coordinate (out of contract): every slab becomes NaN, so the k-DOP
///    overlaps nothing.
/// Fitting permuted or sign-flipped points gives the correspondingly permuted slabs bit for bit
/// (for direction sets closed under the operation).
template <int K>
Kdop<K> fit_kdop(std::span<const Vec3> points);

/// True when the two k-DOPs overlap on every slab (closed intervals: touching counts). Exact:
/// it only compares the stored bounds; with kdops fitted by fit_kdop it is conservative, and
/// reports overlap for point sets whose exact k-DOPs are apart by less than the outward
/// rounding (2^-48 of the largest coordinate). NaN slabs: false. Symmetric in a and b.
template <int K>
bool test_kdop_kdop(const Kdop<K>& a, const Kdop<K>& b) {
  for (int i = 0; i < K / 2; ++i) {
    if (!(a.lo[i] <= b.hi[i]) || !(b.lo[i] <= a.hi[i])) return false;  // NaN: false
  }
  return true;
}

}  // namespace cc
