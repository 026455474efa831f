// broadphase's second opinions from Bullet: its two broadphases, driven frame by frame as a
// btCollisionWorld drives them (a proxy created when a box appears, its AABB set every frame,
// destroyed when the box goes, then calculateOverlappingPairs), the boxes given as the proxies'
// AABBs:
//  - btAxisSweep3, the incremental sweep-and-prune of the notes, over the hull of every box of the
//    case (its world), in 16-bit quantized coordinates rounded outward;
//  - btDbvtBroadphase, two dynamic AABB trees whose moving leaves are fattened by a margin (0.05)
//    and whose pair cache is cleaned a fraction at a time.
// Both hand their candidate pairs to a narrow phase; as its first step, each candidate is kept
// when TestAabbAgainstAabb2 finds the two boxes overlapping (so neither the quantization, the
// margin nor a stale pair is a false pair here; the boxes as given, since btAxisSweep3's proxies
// record their AABB only from their first setAabb on). The band is exact: what this
// asks is whether a broadphase misses an overlapping pair. Boxes with NaN, infinite or inverted
// bounds are not asked (Bullet asserts lo <= hi; its quantization needs a finite world).
#include <BulletCollision/BroadphaseCollision/btAxisSweep3.h>
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/BroadphaseCollision/btOverlappingPairCache.h>
#include <LinearMath/btAabbUtil2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "oracle/bullet/convert.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {
namespace {

enum class Broadphase { axis_sweep, dbvt };

Opinion run_broadphase(Broadphase kind, const harness::BroadphaseInput& in) {
  btVector3 world_lo(BT_LARGE_FLOAT, BT_LARGE_FLOAT, BT_LARGE_FLOAT), world_hi = -world_lo;
  std::size_t slots = 0;
  for (const auto& frame : in.frames) {
    slots = std::max(slots, frame.size());
    for (const auto& box : frame) {
      if (!box) continue;
      for (int k = 0; k < 3; ++k) {
        if (!(std::isfinite(box->lo[k]) && std::isfinite(box->hi[k]) && box->lo[k] <= box->hi[k])) {
          return not_applicable("a box with NaN, infinite or inverted bounds");
        }
      }
      world_lo.setMin(to_bullet(box->lo));
      world_hi.setMax(to_bullet(box->hi));
    }
  }
  std::unique_ptr<btBroadphaseInterface> broadphase;
  if (kind == Broadphase::axis_sweep) {
    if (slots + 2 > 16384) return not_applicable("more boxes than btAxisSweep3's 16-bit handles");
    if (!(world_lo.x() <= world_hi.x())) world_lo = btVector3(-1, -1, -1), world_hi = btVector3(1, 1, 1);  // no box at all
    // Its quantization divides by the world's extent: a world flat on an axis (every box flat
    // there) is padded on every axis by 2^-8 of its size (or of 1).
    double pad = 1;
    for (int k = 0; k < 3; ++k) pad = std::max({pad, world_hi[k] - world_lo[k], std::fabs(world_lo[k]), std::fabs(world_hi[k])});
    pad /= 256;
    world_lo -= btVector3(pad, pad, pad), world_hi += btVector3(pad, pad, pad);
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(world_hi[k] - world_lo[k])) return not_applicable("a world too large for btAxisSweep3's quantization");
    }
    broadphase = std::make_unique<btAxisSweep3>(world_lo, world_hi, static_cast<unsigned short>(slots + 2), nullptr, true);
  } else {
    broadphase = std::make_unique<btDbvtBroadphase>();
  }
  std::vector<btBroadphaseProxy*> proxies(slots, nullptr);
  Opinion o = answered(false);
  for (const auto& frame : in.frames) {
    for (std::size_t i = 0; i < slots; ++i) {
      const bool present = i < frame.size() && frame[i].has_value();
      if (present && proxies[i] == nullptr) {
        proxies[i] = broadphase->createProxy(to_bullet(frame[i]->lo), to_bullet(frame[i]->hi), 0,
                                             reinterpret_cast<void*>(i), btBroadphaseProxy::DefaultFilter,
                                             btBroadphaseProxy::AllFilter, nullptr);
      } else if (present) {
        broadphase->setAabb(proxies[i], to_bullet(frame[i]->lo), to_bullet(frame[i]->hi), nullptr);
      } else if (proxies[i] != nullptr) {
        broadphase->destroyProxy(proxies[i], nullptr);
        proxies[i] = nullptr;
      }
    }
    broadphase->calculateOverlappingPairs(nullptr);
    std::vector<harness::FacePair> pairs;
    btBroadphasePairArray& candidates = broadphase->getOverlappingPairCache()->getOverlappingPairArray();
    for (int p = 0; p < candidates.size(); ++p) {
      const btBroadphaseProxy* a = candidates[p].m_pProxy0;
      const btBroadphaseProxy* b = candidates[p].m_pProxy1;
      if (a == nullptr || b == nullptr) continue;
      const auto i = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(a->m_clientObject));
      const auto j = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(b->m_clientObject));
      // The boxes as given (btAxisSweep3's proxies record their AABB only from the first setAabb on).
      if (i >= frame.size() || j >= frame.size() || !frame[i] || !frame[j]) continue;
      if (!TestAabbAgainstAabb2(to_bullet(frame[i]->lo), to_bullet(frame[i]->hi), to_bullet(frame[j]->lo), to_bullet(frame[j]->hi))) continue;
      pairs.push_back(std::minmax(i, j));
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    o.answer.hit |= !pairs.empty();
    o.answer.frames.push_back(std::move(pairs));
  }
  for (btBroadphaseProxy* p : proxies) {
    if (p != nullptr) broadphase->destroyProxy(p, nullptr);
  }
  return o;
}

}  // namespace

template <>
const std::vector<Party<harness::BroadphaseInput>>& bullet_parties() {
  constexpr Band kBand{0, BandSides::exact, 0, "candidates kept by TestAabbAgainstAabb2 on the given bounds: a missed pair is wrong"};
  static const std::vector<Party<harness::BroadphaseInput>> parties = {
      {"bullet.btAxisSweep3", kBand, [](const harness::BroadphaseInput& in) { return run_broadphase(Broadphase::axis_sweep, in); }},
      {"bullet.btDbvtBroadphase", kBand, [](const harness::BroadphaseInput& in) { return run_broadphase(Broadphase::dbvt, in); }}};
  return parties;
}

}  // namespace cc::bullet_oracle
