#include "collide/ray_aabb_batch.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "collide/ray_slab_bound.h"
#include "collide/simd_lanes.h"

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
constexpr double kA = 1 - bounds::kRaySlab.relative, kB = 1 + bounds::kRaySlab.relative;

// What the kernel reads: the boxes' arrays, each slab's near and far bound arrays as the
// direction's sign picks them, and the ray's scaled parameters.
struct Slabs {
  const double* lo[3];
  const double* hi[3];
  const double* near[3];
  const double* far[3];
  double origin[3], inv[3], tmin, tmax;

  Slabs(const PreparedRay& r, const AabbSoa& b)
      : lo{b.lo_x.data(), b.lo_y.data(), b.lo_z.data()},
        hi{b.hi_x.data(), b.hi_y.data(), b.hi_z.data()},
        origin{r.ray.origin.x, r.ray.origin.y, r.ray.origin.z},
        inv{r.inv_scaled[0], r.inv_scaled[1], r.inv_scaled[2]},
        tmin(r.tmin),
        tmax(r.tmax) {
    for (int a = 0; a < 3; ++a) {
      near[a] = r.negative[a] ? hi[a] : lo[a];
      far[a] = r.negative[a] ? lo[a] : hi[a];
    }
  }
};

// The kernel: boxes i .. i + L::kWidth - 1 against the ray, for the slabs marked parallel in P;
// bit j of the result is box i + j's answer. Each lane computes what intersect_ray_aabb computes
// on its box, in the same order: the entry and exit over the slabs that are not parallel, both
// widened, clipped to [tmin, tmax] and compared; the origin against each parallel slab; then, on
// the hit path only, the box's contract (no NaN or infinite bound, lo <= hi). The lanes' min and
// max differ from std::min and std::max only for NaN, which comes only from a box out of
// contract (rejected by the contract), and in the sign of a zero entry or exit, which the
// widening maps to the same double.
template <class L, int P, bool kAhead>
inline unsigned kernel(const Slabs& s, std::size_t i) {
  using D = typename L::D;
  // The entry and exit start from the first slab that is not parallel (there from -inf and
  // +inf, which max and min would replace by it).
  constexpr int first = (P & 1) == 0 ? 0 : ((P & 2) == 0 ? 1 : ((P & 4) == 0 ? 2 : 3));
  D enter = L::broadcast(-INFINITY), exit = L::broadcast(INFINITY);
  for (int a = first; a < 3; ++a) {
    if ((P >> a) & 1) continue;
    const D o = L::broadcast(s.origin[a]), inv = L::broadcast(s.inv[a]);
    const D near = (L::load(s.near[a] + i) - o) * inv, far = (L::load(s.far[a] + i) - o) * inv;
    enter = a == first ? near : L::max(enter, near);
    exit = a == first ? far : L::min(exit, far);
  }
  const D ka = L::broadcast(kA), kb = L::broadcast(kB), slack = L::broadcast(fp::subnormal_slack);
  typename L::M hit;
  if constexpr (kAhead) {
    // tmin >= 0: a widened entry below 0 loses to tmin, whichever product widened it, so the
    // entry takes t A; an exit below 0 loses to the entry (>= tmin >= 0) both ways, or is
    // subnormal, where t A and t B round to t: it takes t B. The same decision, 4 fewer steps.
    hit = L::max(L::broadcast(s.tmin), enter * ka - slack) <= L::min(L::broadcast(s.tmax), exit * kb + slack);
  } else {
    const D enter_low = L::max(L::broadcast(s.tmin), L::min(enter * ka, enter * kb) - slack);
    const D exit_high = L::min(L::broadcast(s.tmax), L::max(exit * ka, exit * kb) + slack);
    hit = enter_low <= exit_high;
  }
  for (int a = 0; a < 3; ++a) {
    if (!((P >> a) & 1)) continue;
    const D o = L::broadcast(s.origin[a]);
    hit = hit & (o >= L::load(s.lo[a] + i)) & (o <= L::load(s.hi[a] + i));
  }
  if (L::bits(hit) == 0) return 0;
  const D minus_inf = L::broadcast(-INFINITY), plus_inf = L::broadcast(INFINITY);
  for (int a = 0; a < 3; ++a) {
    const D lo = L::load(s.lo[a] + i), hi = L::load(s.hi[a] + i);
    hit = hit & (lo <= hi) & (lo > minus_inf) & (hi < plus_inf);
  }
  return L::bits(hit);
}

// Every box: blocks of L::kWidth, each block's bits placed in its word, then the boxes left over
// one at a time through the same kernel. Returns the number of hits.
template <class L, int P, bool kAhead>
inline std::size_t all_boxes(const PreparedRay& r, const AabbSoa& b, std::uint64_t* hits) {
  constexpr std::size_t w = L::kWidth;
  const Slabs s(r, b);
  const std::size_t n = b.size();
  std::size_t count = 0, i = 0;
  for (std::size_t word = 0; word < hit_words(n); ++word) {
    std::uint64_t bits = 0;
    const std::size_t end = std::min(n, 64 * word + 64);
    for (; i + w <= end; i += w) bits |= static_cast<std::uint64_t>(kernel<L, P, kAhead>(s, i)) << (i % 64);
    for (; i < end; ++i) bits |= static_cast<std::uint64_t>(kernel<simd::Scalar, P, kAhead>(s, i)) << (i % 64);
    hits[word] = bits;
    count += static_cast<std::size_t>(std::popcount(bits));
  }
  return count;
}

using Run = std::size_t (*)(const PreparedRay&, const AabbSoa&, std::uint64_t*);

// P (0..15): bits 0-2 the parallel slabs, bit 3 tmin >= 0.
template <int P>
[[gnu::flatten]] std::size_t run_scalar(const PreparedRay& r, const AabbSoa& b, std::uint64_t* hits) {
  return all_boxes<simd::Scalar, P & 7, (P >> 3) != 0>(r, b, hits);
}
template <int P>
[[gnu::target("avx2"), gnu::flatten]] std::size_t run_avx2(const PreparedRay& r, const AabbSoa& b, std::uint64_t* hits) {
  return all_boxes<simd::Avx2, P & 7, (P >> 3) != 0>(r, b, hits);
}
template <int P>
[[gnu::target("avx512f,avx512dq"), gnu::flatten]] std::size_t run_avx512(const PreparedRay& r, const AabbSoa& b,
                                                                         std::uint64_t* hits) {
  return all_boxes<simd::Avx512, P & 7, (P >> 3) != 0>(r, b, hits);
}

// Per kernel (in simd::Kernel's order), the runs for P = 0..15.
template <int... P>
constexpr std::array<std::array<Run, 16>, 3> runs(std::integer_sequence<int, P...>) {
  return {{{run_scalar<P>...}, {run_avx2<P>...}, {run_avx512<P>...}}};
}
constexpr auto kRuns = runs(std::make_integer_sequence<int, 16>{});
static_assert(static_cast<int>(simd::Kernel::scalar) == 0 && static_cast<int>(simd::Kernel::avx2) == 1 &&
              static_cast<int>(simd::Kernel::avx512) == 2);

}  // namespace

std::size_t test_ray_aabbs(const Ray& ray, const AabbSoa& boxes, std::span<std::uint64_t> hits) {
  return test_ray_aabbs(ray, boxes, hits, simd::selected());
}

std::size_t test_ray_aabbs(const Ray& ray, const AabbSoa& boxes, std::span<std::uint64_t> hits, simd::Kernel kernel) {
  if (const auto why = simd::unsupported_reason(kernel)) {
    throw std::invalid_argument("test_ray_aabbs: the " + std::string(simd::to_string(kernel)) + " kernel: " + *why);
  }
  const std::size_t n = boxes.size();
  if (hits.size() < hit_words(n)) throw std::invalid_argument("test_ray_aabbs: fewer hit words than hit_words(boxes)");
  const PreparedRay r(ray);
  if (!r.in_contract) {
    std::fill(hits.begin(), hits.begin() + static_cast<std::ptrdiff_t>(hit_words(n)), std::uint64_t{0});
    return 0;
  }
  if (r.subnormal != 0) {
    // A component that is subnormal once scaled: the scalar test computes its slab in long
    // double, a path too rare to vectorise. Box by box, then.
    std::fill(hits.begin(), hits.begin() + static_cast<std::ptrdiff_t>(hit_words(n)), std::uint64_t{0});
    std::size_t count = 0;
    for (std::size_t b = 0; b < n; ++b) {
      const bool hit = intersect_ray_aabb(r, boxes[b]).hit;
      hits[b / 64] |= static_cast<std::uint64_t>(hit) << (b % 64);
      count += hit;
    }
    return count;
  }
  const std::size_t variant = static_cast<std::size_t>(r.parallel) | (r.tmin >= 0 ? 8 : 0);
  return kRuns[static_cast<std::size_t>(kernel)][variant](r, boxes, hits.data());
}

}  // namespace cc
