#include "collide/kdop.h"

#include <utility>

#include "collide/kdop_bound.h"
#include "collide/record_sink.h"
#include "collide/simd_lanes.h"

namespace cc {
namespace {

constexpr int terms(const KdopDirection& d) { return (d.x != 0) + (d.y != 0) + (d.z != 0); }

// Slab i of the k-DOP grown by point p: the projection s = sum3 of the three exact products
// d_j p_j, widened by `widen` times sum3 of their magnitudes. The plain definition.
template <int K, class Records>
void grow_slab(Kdop<K>& dop, int i, const KdopDirection& d, double widen, const Vec3& p, Records& records) {
  const double tx = d.x * p.x, ty = d.y * p.y, tz = d.z * p.z;  // exact
  const double s = fp::sum3(tx, ty, tz);
  const double pad = widen * fp::sum3(std::fabs(tx), std::fabs(ty), std::fabs(tz));
  if (terms(d) > 1) records.add(bounds::KdopProjection{d, p, s, pad});
  dop.lo[i] = std::min(dop.lo[i], s - pad);
  dop.hi[i] = std::max(dop.hi[i], s + pad);
}

// The same, specialised at compile time to the direction's shape, with the same result bit for
// bit. For a 1-term direction the other two products are +-0: when the remaining term t is
// nonzero, every order of summation gives t, and pad = 0 * |t| = +0, so the slab grows by t. For
// a 2-term direction, when the two terms' sum s is nonzero every order gives fl(s), and the
// magnitudes' sum is fl(|t1| + |t2|). A zero sum (where the sign of zero depends on the order)
// and 3-term directions take the plain definition. Non-finite points are overwritten anyway.
template <int K, std::size_t I, class Records>
inline void grow_slab_fast(Kdop<K>& dop, const Vec3& p, Records& records) {
  constexpr KdopDirection d = kdop_directions<K>()[I];
  constexpr int n = terms(d);
  if constexpr (n == 1) {
    const double t = d.x != 0 ? d.x * p.x : (d.y != 0 ? d.y * p.y : d.z * p.z);
    if (t != 0) {
      dop.lo[I] = std::min(dop.lo[I], t);
      dop.hi[I] = std::max(dop.hi[I], t);
      return;
    }
    grow_slab(dop, static_cast<int>(I), d, 0.0, p, records);
  } else if constexpr (n == 2) {
    const double t1 = d.x != 0 ? d.x * p.x : d.y * p.y;
    const double t2 = d.z != 0 ? d.z * p.z : d.y * p.y;
    const double s = t1 + t2;
    if (s != 0) {
      const double pad = bounds::kKdopProjection * (std::fabs(t1) + std::fabs(t2));
      records.add(bounds::KdopProjection{d, p, s, pad});
      dop.lo[I] = std::min(dop.lo[I], s - pad);
      dop.hi[I] = std::max(dop.hi[I], s + pad);
      return;
    }
    grow_slab(dop, static_cast<int>(I), d, bounds::kKdopProjection, p, records);
  } else {
    grow_slab(dop, static_cast<int>(I), d, bounds::kKdopProjection, p, records);
  }
}

// Outward rounding per direction: zero for the exact single-coordinate projections; for a sum of
// two or three coordinates bounds::kKdopProjection of its magnitude (see grow_slab).
template <int K, class Records>
Kdop<K> fit(std::span<const Vec3> points, Records& records) {
  Kdop<K> dop;
  bool finite_points = true;
  for (const Vec3& p : points) {
    finite_points &= finite(p);
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      (grow_slab_fast<K, I>(dop, p, records), ...);
    }(std::make_index_sequence<K / 2>{});
  }
  if (!finite_points) {
    dop.lo.fill(std::numeric_limits<double>::quiet_NaN());
    dop.hi.fill(std::numeric_limits<double>::quiet_NaN());
  }
  return dop;
}

// The same fit, L::kWidth points at a time: lane j of every slab's bounds grows by the points
// j, j + w, j + 2w, ... exactly as fit() grows a slab by one point (the candidate first in min
// and max, so that a NaN candidate is ignored and ties keep the earlier value, as std::min and
// std::max do), and the lanes are merged at the end. For a point set with finite coordinates the
// bounds are fit()'s bit for bit, except that a bound of 0 may differ from it in the sign of the
// zero (fit()'s sign depends on which point came first): false then, and the caller takes fit().
template <class L, int K>
bool fit_lanes(std::span<const Vec3> points, Kdop<K>& dop) {
  using D = typename L::D;
  constexpr int w = L::kWidth, slabs = K / 2;
  constexpr auto dirs = kdop_directions<K>();
  const std::size_t n = points.size();
  D lo[slabs], hi[slabs];
  for (int i = 0; i < slabs; ++i) lo[i] = L::broadcast(INFINITY), hi[i] = L::broadcast(-INFINITY);
  const D widen = L::broadcast(bounds::kKdopProjection);
  bool finite_points = true;
  for (std::size_t first = 0; first < n; first += w) {
    double xs[w], ys[w], zs[w];  // the block's points by coordinate; past the end, the last again
    for (int j = 0; j < w; ++j) {
      const Vec3& p = points[std::min(first + j, n - 1)];
      finite_points &= finite(p);
      xs[j] = p.x, ys[j] = p.y, zs[j] = p.z;
    }
    const D coordinate[3] = {L::load(xs), L::load(ys), L::load(zs)};
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ([&] {
        constexpr KdopDirection d = dirs[I];
        constexpr int sign[3] = {d.x, d.y, d.z};
        D t[3];  // the exact products d_k p_k of the direction's terms
        int m = 0;
        for (int k = 0; k < 3; ++k) {
          if (sign[k] != 0) t[m++] = sign[k] > 0 ? coordinate[k] : coordinate[k] * L::broadcast(-1.0);
        }
        D low, high;
        if (m == 1) {
          low = high = t[0];
        } else if (m == 2) {
          const D s = t[0] + t[1], pad = widen * (L::abs(t[0]) + L::abs(t[1]));
          low = s - pad, high = s + pad;
        } else {
          const auto sum3 = [](const D& a, const D& b, const D& c) {  // fp::sum3, lane by lane
            const D x = (a + b) + c, y = (a + c) + b, z = (b + c) + a;
            return L::max(L::min(x, y), L::min(L::max(x, y), z));
          };
          const D s = sum3(t[0], t[1], t[2]), pad = widen * sum3(L::abs(t[0]), L::abs(t[1]), L::abs(t[2]));
          low = s - pad, high = s + pad;
        }
        lo[I] = L::min(low, lo[I]);
        hi[I] = L::max(high, hi[I]);
      }(), ...);
    }(std::make_index_sequence<slabs>{});
  }
  if (!finite_points) return false;  // fit() fills the bounds with NaN
  for (int i = 0; i < slabs; ++i) {
    double low[w], high[w];
    L::store(low, lo[i]), L::store(high, hi[i]);
    for (int j = 0; j < w; ++j) {
      dop.lo[i] = std::min(dop.lo[i], low[j]);
      dop.hi[i] = std::max(dop.hi[i], high[j]);
    }
    if (dop.lo[i] == 0 || dop.hi[i] == 0) return false;
  }
  return true;
}

template <int K>
[[gnu::flatten]] bool fit_scalar(std::span<const Vec3> points, Kdop<K>& dop) {
  return fit_lanes<simd::Scalar, K>(points, dop);
}
template <int K>
[[gnu::target("avx2"), gnu::flatten]] bool fit_avx2(std::span<const Vec3> points, Kdop<K>& dop) {
  return fit_lanes<simd::Avx2, K>(points, dop);
}
template <int K>
[[gnu::target("avx512f,avx512dq"), gnu::flatten]] bool fit_avx512(std::span<const Vec3> points, Kdop<K>& dop) {
  return fit_lanes<simd::Avx512, K>(points, dop);
}

}  // namespace

template <int K>
Kdop<K> fit_kdop(std::span<const Vec3> points) {
  Kdop<K> dop;
  bool done = false;
  switch (simd::selected()) {
    case simd::Kernel::scalar: done = fit_scalar<K>(points, dop); break;
    case simd::Kernel::avx2: done = fit_avx2<K>(points, dop); break;
    case simd::Kernel::avx512: done = fit_avx512<K>(points, dop); break;
  }
  if (done) return dop;
  bounds::NoRecords none;
  return fit<K>(points, none);
}

template <int K>
Kdop<K> fit_kdop(std::span<const Vec3> points, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return fit<K>(points, into);
}

#define CC_INSTANTIATE(K)                                  \
  template Kdop<K> fit_kdop<K>(std::span<const Vec3>); \
  template Kdop<K> fit_kdop<K>(std::span<const Vec3>, bounds::Records&);
CC_INSTANTIATE(6)
CC_INSTANTIATE(14)
CC_INSTANTIATE(16)
CC_INSTANTIATE(18)
CC_INSTANTIATE(24)
CC_INSTANTIATE(26)
#undef CC_INSTANTIATE

}  // namespace cc
