// How far a k-DOP reaches along a direction, bounded from above through three of its slabs: the
// approximate update of a hierarchy re-fits b's k-DOPs (and boxes) in a's frame this way, with
// no corners stored or computed.
#pragma once

#include <array>

#include "collide/kdop.h"

namespace cc {

/// A direction m written as c_0 s_0 + c_1 s_1 + c_2 s_2 with c_j >= 0, where s_j are three of a
/// k-DOP's half-space normals: normal h < K/2 is +d_h (bounded by hi[h]), normal K/2 + i is
/// -d_i (bounded by -lo[i]). Then every point x of a k-DOP has m . x <= sum c_j bound_j
/// (support_bound), and the bound is the k-DOP's support (max m . x over it) when the three
/// slabs meet at a vertex of it, as for every box; otherwise it lies a little above.
///  - The three are the corners of a face of the convex hull of the normalised normals, which
///    cover every direction; for a box, the octant of m, with c_j = |m_j| exactly.
///  - Rounded: the combination differs from m by at most 2^-46 max|m_k| in each component; the
///    coefficients sum to at most 9 max|m_k|.
///  - m finite; m = 0 gives c = 0.
template <int K>
struct KdopCone {
  std::array<int, 3> normal{};
  std::array<double, 3> coefficient{};
};

template <int K>
KdopCone<K> kdop_cone(const Vec3& m);

/// sum c_j bound_j for the k-DOP (each product and the sum rounded: an error of at most
/// 3u sum c_j |bound_j|). An empty k-DOP gives -inf or NaN.
template <int K>
[[gnu::always_inline]] inline double support_bound(const Kdop<K>& dop, const KdopCone<K>& cone) {
  double term[3];
  for (int j = 0; j < 3; ++j) {
    const int h = cone.normal[j];
    term[j] = cone.coefficient[j] * (h < K / 2 ? dop.hi[h] : -dop.lo[h - K / 2]);
  }
  return fp::sum3(term[0], term[1], term[2]);
}

}  // namespace cc
