#include "collide/kdop.h"

#include <utility>

#include "collide/bound_records.h"

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

}  // namespace

template <int K>
Kdop<K> fit_kdop(std::span<const Vec3> points) {
  bounds::NoRecords none;
  return fit<K>(points, none);
}

template <int K>
Kdop<K> fit_kdop(std::span<const Vec3> points, bounds::Records& records) {
  return fit<K>(points, records);
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
