#include "collide/kdop_corners.h"

#include <algorithm>

namespace cc {
namespace {

Vec3 vec(const KdopDirection& d) { return {double(d.x), double(d.y), double(d.z)}; }

}  // namespace

template <int K>
std::vector<Vec3> kdop_corners(const Kdop<K>& dop) {
  constexpr auto dirs = kdop_directions<K>();
  constexpr int n = K / 2;
  double magnitude = 0;
  for (int i = 0; i < n; ++i) {
    if (!(dop.lo[i] <= dop.hi[i]) || !fp::finite(dop.lo[i]) || !fp::finite(dop.hi[i])) return {};
    magnitude = std::max({magnitude, std::fabs(dop.lo[i]), std::fabs(dop.hi[i])});
  }
  const double tolerance = 0x1p-46 * magnitude;
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        const Vec3 di = vec(dirs[i]), dj = vec(dirs[j]), dk = vec(dirs[k]);
        // Cramer's rule: x = (b_i (dj x dk) + b_j (dk x di) + b_k (di x dj)) / det; the cross
        // products and the determinant are small integers, computed exactly.
        const Vec3 ci = cross(dj, dk), cj = cross(dk, di), ck = cross(di, dj);
        const double det = dot(di, ci);
        if (det == 0) continue;
        for (int choice = 0; choice < 8; ++choice) {
          const double bi = (choice & 1) ? dop.hi[i] : dop.lo[i], bj = (choice & 2) ? dop.hi[j] : dop.lo[j],
                       bk = (choice & 4) ? dop.hi[k] : dop.lo[k];
          Vec3 x;
          for (int c = 0; c < 3; ++c) x[c] = fp::sum3(bi * ci[c], bj * cj[c], bk * ck[c]) / det;
          bool inside = true;
          for (int m = 0; m < n && inside; ++m) {
            const double s = dot(vec(dirs[m]), x);
            inside = s >= dop.lo[m] - tolerance && s <= dop.hi[m] + tolerance;
          }
          if (inside) out.push_back(x);
        }
      }
    }
  }
  // The fit's outward rounding bevels every edge and corner by about 2^-51 of the magnitude,
  // which splits a corner into a speck of nearby ones: keep one corner per speck.
  const double speck = 0x1p-49 * magnitude;
  std::vector<Vec3> kept;
  for (const Vec3& x : out) {
    const bool near = std::any_of(kept.begin(), kept.end(), [&](const Vec3& k) { return max_abs(x - k) <= speck; });
    if (!near) kept.push_back(x);
  }
  return kept;
}

template std::vector<Vec3> kdop_corners<6>(const Kdop<6>&);
template std::vector<Vec3> kdop_corners<14>(const Kdop<14>&);
template std::vector<Vec3> kdop_corners<16>(const Kdop<16>&);
template std::vector<Vec3> kdop_corners<18>(const Kdop<18>&);
template std::vector<Vec3> kdop_corners<24>(const Kdop<24>&);
template std::vector<Vec3> kdop_corners<26>(const Kdop<26>&);

}  // namespace cc
