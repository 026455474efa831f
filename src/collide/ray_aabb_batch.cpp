#include "collide/ray_aabb_batch.h"

#include <immintrin.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace cc {

void AabbSoa::push_back(const Aabb& box) {
  lo_x.push_back(box.lo.x), lo_y.push_back(box.lo.y), lo_z.push_back(box.lo.z);
  hi_x.push_back(box.hi.x), hi_y.push_back(box.hi.y), hi_z.push_back(box.hi.z);
}

namespace {

// The widening of ray_aabb.cpp's lower() and upper(): lower(t) = t (1 -+ 8u) - slack for t > 0
// (t <= 0). Rounding is monotone, so t (1 - 8u) <= t (1 + 8u) exactly when t >= 0, and lower(t)
// is min(t A, t B) - slack; upper(t) = max(t A, t B) + slack. Both are applied, as there, to
// the largest entry and the smallest exit over the slabs.
constexpr double kA = 1 - 8 * fp::u, kB = 1 + 8 * fp::u;

// Box i is in the scalar test's contract: no NaN or infinite bound and lo <= hi on every axis.
// (lo <= hi < inf and -inf < lo <= hi make both finite; NaN fails lo <= hi.)
inline bool box_in_contract(double lo, double hi) { return (lo <= hi) & (lo > -INFINITY) & (hi < INFINITY); }

// Box i against the ray, for the slabs marked parallel in P: the steps of the vector kernels
// below on one box (their tails, and the whole batch without AVX2).
template <int P>
inline bool one_box(const PreparedRay& r, const AabbSoa& b, std::size_t i) {
  const double lo[3] = {b.lo_x[i], b.lo_y[i], b.lo_z[i]}, hi[3] = {b.hi_x[i], b.hi_y[i], b.hi_z[i]};
  bool ok = true;
  double enter = -INFINITY, exit = INFINITY;
  for (int a = 0; a < 3; ++a) {
    ok &= box_in_contract(lo[a], hi[a]);
    if ((P >> a) & 1) {
      ok &= r.ray.origin[a] >= lo[a] && r.ray.origin[a] <= hi[a];
      continue;
    }
    enter = std::max(enter, ((r.negative[a] ? hi[a] : lo[a]) - r.ray.origin[a]) * r.inv_scaled[a]);
    exit = std::min(exit, ((r.negative[a] ? lo[a] : hi[a]) - r.ray.origin[a]) * r.inv_scaled[a]);
  }
  const double enter_low = std::max(r.tmin, std::min(enter * kA, enter * kB) - fp::subnormal_slack);
  const double exit_high = std::min(r.tmax, std::max(exit * kA, exit * kB) + fp::subnormal_slack);
  return ok & (enter_low <= exit_high);
}

template <int P>
std::size_t run_scalar(const PreparedRay& r, const AabbSoa& b, std::uint8_t* hits, std::size_t from) {
  std::size_t count = 0;
  for (std::size_t i = from; i < b.size(); ++i) count += hits[i] = one_box<P>(r, b, i);
  return count;
}

// hits[0..8) from the bits of a mask: entry m holds byte j = bit j of m.
constexpr std::array<std::uint64_t, 256> kMaskBytes = [] {
  std::array<std::uint64_t, 256> t{};
  for (std::uint64_t m = 0; m < 256; ++m) {
    for (int j = 0; j < 8; ++j) t[m] |= ((m >> j) & 1) << (8 * j);
  }
  return t;
}();

// The same steps on 8 boxes at a time (AVX-512) and on 4 (AVX2). Every lane computes what
// one_box computes; min and max differ from std::min and std::max only for NaN operands, which
// occur only in lanes whose box is out of contract, and those are rejected by the contract
// check that follows any candidate hit. (GCC 12's AVX-512 header trips
// -Wmaybe-uninitialized inside _mm512_min_pd and _mm512_max_pd: a known false positive.)
#pragma GCC diagnostic push
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
template <int P>
[[gnu::target("avx512f,avx512dq")]] std::size_t run_avx512(const PreparedRay& r, const AabbSoa& b, std::uint8_t* hits) {
  const double* lo[3] = {b.lo_x.data(), b.lo_y.data(), b.lo_z.data()};
  const double* hi[3] = {b.hi_x.data(), b.hi_y.data(), b.hi_z.data()};
  const __m512d ka = _mm512_set1_pd(kA), kb = _mm512_set1_pd(kB), slack = _mm512_set1_pd(fp::subnormal_slack);
  const __m512d minus_inf = _mm512_set1_pd(-INFINITY), plus_inf = _mm512_set1_pd(INFINITY);
  const __m512d tmin = _mm512_set1_pd(r.tmin), tmax = _mm512_set1_pd(r.tmax);
  std::size_t count = 0, i = 0;
  for (; i + 8 <= b.size(); i += 8) {
    __mmask8 ok = 0xFF;
    __m512d enter = minus_inf, exit = plus_inf;
    for (int a = 0; a < 3; ++a) {
      const __m512d l = _mm512_loadu_pd(lo[a] + i), h = _mm512_loadu_pd(hi[a] + i);
      const __m512d o = _mm512_set1_pd(r.ray.origin[a]);
      if ((P >> a) & 1) {
        ok = static_cast<__mmask8>(ok & _mm512_cmp_pd_mask(o, l, _CMP_GE_OQ) & _mm512_cmp_pd_mask(o, h, _CMP_LE_OQ));
        continue;
      }
      const __m512d inv = _mm512_set1_pd(r.inv_scaled[a]);
      enter = _mm512_max_pd(enter, _mm512_mul_pd(_mm512_sub_pd(r.negative[a] ? h : l, o), inv));
      exit = _mm512_min_pd(exit, _mm512_mul_pd(_mm512_sub_pd(r.negative[a] ? l : h, o), inv));
    }
    const __m512d low = _mm512_min_pd(_mm512_mul_pd(enter, ka), _mm512_mul_pd(enter, kb));
    const __m512d high = _mm512_max_pd(_mm512_mul_pd(exit, ka), _mm512_mul_pd(exit, kb));
    const __m512d enter_low = _mm512_max_pd(tmin, _mm512_sub_pd(low, slack));
    const __m512d exit_high = _mm512_min_pd(tmax, _mm512_add_pd(high, slack));
    ok = static_cast<__mmask8>(ok & _mm512_cmp_pd_mask(enter_low, exit_high, _CMP_LE_OQ));
    if (ok) {  // the boxes' contract, checked on the hit path only (as the scalar test does)
      for (int a = 0; a < 3; ++a) {
        const __m512d l = _mm512_loadu_pd(lo[a] + i), h = _mm512_loadu_pd(hi[a] + i);
        ok = static_cast<__mmask8>(ok & _mm512_cmp_pd_mask(l, h, _CMP_LE_OQ) & _mm512_cmp_pd_mask(l, minus_inf, _CMP_GT_OQ) &
                                   _mm512_cmp_pd_mask(h, plus_inf, _CMP_LT_OQ));
      }
    }
    std::memcpy(hits + i, &kMaskBytes[ok], 8);
    count += static_cast<std::size_t>(__builtin_popcount(ok));
  }
  return count + run_scalar<P>(r, b, hits, i);
}

template <int P>
[[gnu::target("avx2")]] std::size_t run_avx2(const PreparedRay& r, const AabbSoa& b, std::uint8_t* hits) {
  const double* lo[3] = {b.lo_x.data(), b.lo_y.data(), b.lo_z.data()};
  const double* hi[3] = {b.hi_x.data(), b.hi_y.data(), b.hi_z.data()};
  const __m256d ka = _mm256_set1_pd(kA), kb = _mm256_set1_pd(kB), slack = _mm256_set1_pd(fp::subnormal_slack);
  const __m256d minus_inf = _mm256_set1_pd(-INFINITY), plus_inf = _mm256_set1_pd(INFINITY);
  const __m256d tmin = _mm256_set1_pd(r.tmin), tmax = _mm256_set1_pd(r.tmax);
  std::size_t count = 0, i = 0;
  for (; i + 4 <= b.size(); i += 4) {
    __m256d ok = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    __m256d enter = minus_inf, exit = plus_inf;
    for (int a = 0; a < 3; ++a) {
      const __m256d l = _mm256_loadu_pd(lo[a] + i), h = _mm256_loadu_pd(hi[a] + i);
      const __m256d o = _mm256_set1_pd(r.ray.origin[a]);
      if ((P >> a) & 1) {
        ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(o, l, _CMP_GE_OQ), _mm256_cmp_pd(o, h, _CMP_LE_OQ)));
        continue;
      }
      const __m256d inv = _mm256_set1_pd(r.inv_scaled[a]);
      enter = _mm256_max_pd(enter, _mm256_mul_pd(_mm256_sub_pd(r.negative[a] ? h : l, o), inv));
      exit = _mm256_min_pd(exit, _mm256_mul_pd(_mm256_sub_pd(r.negative[a] ? l : h, o), inv));
    }
    const __m256d low = _mm256_min_pd(_mm256_mul_pd(enter, ka), _mm256_mul_pd(enter, kb));
    const __m256d high = _mm256_max_pd(_mm256_mul_pd(exit, ka), _mm256_mul_pd(exit, kb));
    const __m256d enter_low = _mm256_max_pd(tmin, _mm256_sub_pd(low, slack));
    const __m256d exit_high = _mm256_min_pd(tmax, _mm256_add_pd(high, slack));
    ok = _mm256_and_pd(ok, _mm256_cmp_pd(enter_low, exit_high, _CMP_LE_OQ));
    if (_mm256_movemask_pd(ok)) {  // the boxes' contract, on the hit path only
      for (int a = 0; a < 3; ++a) {
        const __m256d l = _mm256_loadu_pd(lo[a] + i), h = _mm256_loadu_pd(hi[a] + i);
        ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(l, h, _CMP_LE_OQ),
                                             _mm256_and_pd(_mm256_cmp_pd(l, minus_inf, _CMP_GT_OQ),
                                                           _mm256_cmp_pd(h, plus_inf, _CMP_LT_OQ))));
      }
    }
    const int mask = _mm256_movemask_pd(ok);
    const std::uint32_t bytes = static_cast<std::uint32_t>(kMaskBytes[static_cast<std::size_t>(mask)]);
    std::memcpy(hits + i, &bytes, 4);
    count += static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(mask)));
  }
  return count + run_scalar<P>(r, b, hits, i);
}

#pragma GCC diagnostic pop

using Run = std::size_t (*)(const PreparedRay&, const AabbSoa&, std::uint8_t*);

template <int P>
std::size_t run_all_scalar(const PreparedRay& r, const AabbSoa& b, std::uint8_t* hits) {
  return run_scalar<P>(r, b, hits, 0);
}

// Per kernel (in simd::Kernel's order), the runs for P = 0..7.
template <int... P>
constexpr std::array<std::array<Run, 8>, 3> runs(std::integer_sequence<int, P...>) {
  return {{{run_all_scalar<P>...}, {run_avx2<P>...}, {run_avx512<P>...}}};
}
constexpr auto kRuns = runs(std::make_integer_sequence<int, 8>{});
static_assert(static_cast<int>(simd::Kernel::scalar) == 0 && static_cast<int>(simd::Kernel::avx2) == 1 &&
              static_cast<int>(simd::Kernel::avx512) == 2);

}  // namespace

std::size_t test_ray_aabbs(const Ray& ray, const AabbSoa& boxes, std::span<std::uint8_t> hits) {
  return test_ray_aabbs(ray, boxes, hits, simd::selected());
}

std::size_t test_ray_aabbs(const Ray& ray, const AabbSoa& boxes, std::span<std::uint8_t> hits, simd::Kernel kernel) {
  if (const auto why = simd::unsupported_reason(kernel)) {
    throw std::invalid_argument("test_ray_aabbs: the " + std::string(simd::to_string(kernel)) + " kernel: " + *why);
  }
  const std::size_t n = boxes.size();
  if (hits.size() < n) throw std::invalid_argument("test_ray_aabbs: fewer hit slots than boxes");
  const PreparedRay r(ray);
  if (!r.in_contract) {
    std::fill(hits.begin(), hits.begin() + static_cast<std::ptrdiff_t>(n), std::uint8_t{0});
    return 0;
  }
  if (r.subnormal != 0) {
    // A component that is subnormal once scaled: the scalar test computes its slab in long
    // double, a path too rare to vectorise. Box by box, then.
    std::size_t count = 0;
    for (std::size_t b = 0; b < n; ++b) count += hits[b] = intersect_ray_aabb(r, boxes[b]).hit;
    return count;
  }
  return kRuns[static_cast<std::size_t>(kernel)][static_cast<std::size_t>(r.parallel)](r, boxes, hits.data());
}

}  // namespace cc
