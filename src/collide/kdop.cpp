#include "collide/kdop.h"

namespace cc {
namespace {

constexpr int terms(const KdopDirection& d) { return (d.x != 0) + (d.y != 0) + (d.z != 0); }

}  // namespace

template <int K>
Kdop<K> fit_kdop(std::span<const Vec3> points) {
  constexpr auto dirs = kdop_directions<K>();
  // Outward rounding per direction: zero for the exact single-coordinate projections; for a
  // sum of two or three coordinates the error is at most 2u of its magnitude, and 4u also
  // covers the rounding of s +- pad.
  std::array<double, K / 2> widen{};
  for (int i = 0; i < K / 2; ++i) widen[i] = terms(dirs[i]) > 1 ? 4 * fp::u : 0.0;

  Kdop<K> dop;
  bool finite_points = true;
  for (const Vec3& p : points) {
    finite_points &= finite(p);
    for (int i = 0; i < K / 2; ++i) {
      const double tx = dirs[i].x * p.x, ty = dirs[i].y * p.y, tz = dirs[i].z * p.z;  // exact
      const double s = fp::sum3(tx, ty, tz);
      const double pad = widen[i] * fp::sum3(std::fabs(tx), std::fabs(ty), std::fabs(tz));
      dop.lo[i] = std::min(dop.lo[i], s - pad);
      dop.hi[i] = std::max(dop.hi[i], s + pad);
    }
  }
  if (!finite_points) {
    dop.lo.fill(std::numeric_limits<double>::quiet_NaN());
    dop.hi.fill(std::numeric_limits<double>::quiet_NaN());
  }
  return dop;
}

template Kdop<6> fit_kdop<6>(std::span<const Vec3>);
template Kdop<14> fit_kdop<14>(std::span<const Vec3>);
template Kdop<16> fit_kdop<16>(std::span<const Vec3>);
template Kdop<18> fit_kdop<18>(std::span<const Vec3>);
template Kdop<24> fit_kdop<24>(std::span<const Vec3>);
template Kdop<26> fit_kdop<26>(std::span<const Vec3>);

}  // namespace cc
