// Bottom-up building: start from one leaf per triangle and merge, level by level. On each level
// the nodes are ordered along a Morton (Z-order) curve of their volumes' centres, so that
// neighbours in the order are neighbours in space, and each node still unpaired is merged with
// the unpaired node among the next kWindow ones whose merged volume is smallest.
#include <algorithm>
#include <numeric>

#include "collide/bvh_topology.h"

namespace cc::detail {
namespace {

constexpr std::size_t kWindow = 8;

// Spreads the low 10 bits of v so that two zero bits follow each.
std::uint32_t spread(std::uint32_t v) {
  v &= 0x3ff;
  v = (v | (v << 16)) & 0x030000ff;
  v = (v | (v << 8)) & 0x0300f00f;
  v = (v | (v << 4)) & 0x030c30c3;
  v = (v | (v << 2)) & 0x09249249;
  return v;
}

// The 30-bit Morton code of p within the box [lo, hi].
std::uint32_t morton(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  std::uint32_t code = 0;
  for (int k = 0; k < 3; ++k) {
    const double extent = hi[k] - lo[k];
    const double t = extent > 0 ? (p[k] - lo[k]) / extent : 0.0;  // NaN for an infinite extent
    const auto cell = t >= 0 ? static_cast<std::uint32_t>(std::min(t * 1023.0, 1023.0)) : 0u;
    code |= spread(cell) << k;
  }
  return code;
}

}  // namespace

template <class BV>
LinkedTree bottom_up_tree(const Mesh& mesh) {
  using Traits = BoundingVolume<BV>;
  LinkedTree tree;
  std::vector<BV> volumes;
  std::vector<std::int32_t> level;
  for (std::uint32_t f = 0; f < mesh.size(); ++f) {
    const auto p = face_points(mesh, f);
    tree.nodes.push_back({-1, -1, f});
    volumes.push_back(Traits::fit(p));
    level.push_back(static_cast<std::int32_t>(f));
  }
  while (level.size() > 1) {
    Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (std::int32_t n : level) {
      const Vec3 c = Traits::center(volumes[n]);
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
    }
    std::vector<std::pair<std::uint32_t, std::int32_t>> keyed;
    for (std::int32_t n : level) keyed.emplace_back(morton(Traits::center(volumes[n]), lo, hi), n);
    std::sort(keyed.begin(), keyed.end());

    std::vector<bool> paired(keyed.size(), false);
    std::vector<std::int32_t> next;
    for (std::size_t i = 0; i < keyed.size(); ++i) {
      if (paired[i]) continue;
      const std::int32_t a = keyed[i].second;
      std::size_t best = 0;
      BvSize best_size{INFINITY, INFINITY};
      BV best_volume;
      for (std::size_t j = i + 1, seen = 0; j < keyed.size() && seen < kWindow; ++j) {
        if (paired[j]) continue;
        ++seen;
        const BV merged = Traits::merge(volumes[a], volumes[keyed[j].second]);
        // The first candidate is taken even when sizes overflow to infinity and compare equal.
        if (best == 0 || Traits::size(merged) < best_size) best_size = Traits::size(merged), best = j, best_volume = merged;
      }
      paired[i] = true;
      if (best == 0) {  // the last one left: it moves up a level alone
        next.push_back(a);
        continue;
      }
      paired[best] = true;
      tree.nodes.push_back({a, keyed[best].second, 0});
      volumes.push_back(best_volume);
      next.push_back(static_cast<std::int32_t>(tree.nodes.size() - 1));
    }
    level = std::move(next);
  }
  tree.root = level.empty() ? -1 : level[0];
  return tree;
}

#define CC_INSTANTIATE(BV) template LinkedTree bottom_up_tree<BV>(const Mesh&);
CC_FOR_EACH_BOUNDING_VOLUME(CC_INSTANTIATE)
#undef CC_INSTANTIATE

}  // namespace cc::detail
