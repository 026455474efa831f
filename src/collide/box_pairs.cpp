#include "collide/box_pairs.h"

#include <algorithm>
#include <cmath>

namespace cc {

std::vector<ObjectPair> sort_and_sweep(std::span<const Aabb> boxes) {
  struct Endpoint {
    double value;
    ObjectId id;
    bool upper;
  };
  std::vector<Endpoint> list;
  list.reserve(2 * boxes.size());
  for (ObjectId i = 0; i < boxes.size(); ++i) {
    const Aabb& b = boxes[i];
    if (std::isnan(b.lo.x) || std::isnan(b.hi.x) || b.lo.x > b.hi.x) continue;  // overlaps nothing on x
    list.push_back({b.lo.x, i, false});
    list.push_back({b.hi.x, i, true});
  }
  std::sort(list.begin(), list.end(), [](const Endpoint& a, const Endpoint& b) {
    if (a.value != b.value) return a.value < b.value;
    if (a.upper != b.upper) return !a.upper;
    return a.id < b.id;
  });
  std::vector<ObjectId> open;
  std::vector<ObjectPair> out;
  for (const Endpoint& e : list) {
    if (e.upper) {
      open.erase(std::find(open.begin(), open.end(), e.id));
      continue;
    }
    for (ObjectId other : open) {
      if (test_aabb_aabb(boxes[e.id], boxes[other])) out.emplace_back(std::min(e.id, other), std::max(e.id, other));
    }
    open.push_back(e.id);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<ObjectPair> box_pairs_brute_force(std::span<const Aabb> boxes) {
  std::vector<ObjectPair> out;
  for (ObjectId i = 0; i < boxes.size(); ++i) {
    for (ObjectId j = i + 1; j < boxes.size(); ++j) {
      if (test_aabb_aabb(boxes[i], boxes[j])) out.emplace_back(i, j);
    }
  }
  return out;
}

}  // namespace cc
