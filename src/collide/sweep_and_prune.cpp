#include "collide/sweep_and_prune.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cc {
namespace {

std::uint64_t key_of(ObjectId a, ObjectId b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}
ObjectPair pair_of(std::uint64_t key) { return {static_cast<ObjectId>(key >> 32), static_cast<ObjectId>(key & 0xffffffffu)}; }

void check(const Aabb& box, const char* what, ObjectId id) {
  for (int k = 0; k < 3; ++k) {
    if (std::isnan(box.lo[k]) || std::isnan(box.hi[k]) || box.lo[k] > box.hi[k]) {
      throw std::invalid_argument(std::string("SweepAndPrune::") + what + ": box of object " + std::to_string(id) +
                                  " has a NaN or lo > hi on axis " + "xyz"[k]);
    }
  }
}

}  // namespace

// The order of the lists: by value, lower endpoints before upper ones at equal values (so that
// touching boxes overlap).
bool SweepAndPrune::before(const Endpoint& a, const Endpoint& b) {
  if (a.value != b.value) return a.value < b.value;
  return !a.upper && b.upper;
}

ObjectId SweepAndPrune::add(const Aabb& box) {
  const auto id = static_cast<ObjectId>(boxes_.size());
  check(box, "add", id);
  boxes_.push_back(box);
  alive_.push_back(true);
  ++live_;
  // Both endpoints go to the end of each list at +inf, beyond every other box (no overlaps),
  // and reach their places at the next update(), flipping overlaps as they pass others.
  for (auto& list : axes_) {
    list.push_back({INFINITY, id, false});
    list.push_back({INFINITY, id, true});
  }
  return id;
}

void SweepAndPrune::move(ObjectId id, const Aabb& box) {
  if (id >= boxes_.size() || !alive_[id]) throw std::invalid_argument("SweepAndPrune::move: no object " + std::to_string(id));
  check(box, "move", id);
  boxes_[id] = box;
}

void SweepAndPrune::remove(ObjectId id) {
  if (id >= boxes_.size() || !alive_[id]) throw std::invalid_argument("SweepAndPrune::remove: no object " + std::to_string(id));
  // The object's endpoints move past every other one to the end of each list (upper first),
  // which clears its overlaps swap by swap, and are then dropped.
  for (int axis = 0; axis < 3; ++axis) {
    auto& list = axes_[axis];
    for (const bool upper : {true, false}) {
      const std::size_t end = list.size() - (upper ? 1 : 2);
      std::size_t i = 0;
      while (list[i].id != id || list[i].upper != upper) ++i;
      for (; i < end; ++i) {
        flip(axis, list[i + 1], list[i]);
        std::swap(list[i], list[i + 1]);
        ++swaps_;
      }
    }
    list.resize(list.size() - 2);
  }
  alive_[id] = false;
  --live_;
}

void SweepAndPrune::set_overlap(std::uint64_t key, bool overlapping) {
  changed_.emplace(key, !overlapping);  // keeps the status at the last update
  if (overlapping) {
    overlapping_.insert(key);
  } else {
    overlapping_.erase(key);
  }
}

// `moving_left` now sorts before `moved_right`, which sorted before it.
void SweepAndPrune::flip(int axis, const Endpoint& moving_left, const Endpoint& moved_right) {
  if (moving_left.upper == moved_right.upper || moving_left.id == moved_right.id) return;
  const std::uint64_t key = key_of(moving_left.id, moved_right.id);
  const auto bit = static_cast<std::uint8_t>(1u << axis);
  if (!moving_left.upper) {  // a lower endpoint passes an upper one: the intervals now overlap
    std::uint8_t& bits = axis_bits_[key];
    bits |= bit;
    if (bits == 7) set_overlap(key, true);
  } else {  // an upper endpoint passes a lower one: they no longer overlap
    auto it = axis_bits_.find(key);
    if (it == axis_bits_.end()) return;  // cannot happen: the pair overlapped on this axis
    if (it->second == 7) set_overlap(key, false);
    it->second &= static_cast<std::uint8_t>(~bit);
    if (it->second == 0) axis_bits_.erase(it);
  }
}

void SweepAndPrune::resort(int axis) {
  auto& list = axes_[axis];
  for (std::size_t i = 1; i < list.size(); ++i) {
    for (std::size_t j = i; j > 0 && before(list[j], list[j - 1]); --j) {
      flip(axis, list[j], list[j - 1]);
      std::swap(list[j], list[j - 1]);
      ++swaps_;
    }
  }
}

PairChanges SweepAndPrune::update() {
  for (int axis = 0; axis < 3; ++axis) {
    for (Endpoint& e : axes_[axis]) e.value = e.upper ? boxes_[e.id].hi[axis] : boxes_[e.id].lo[axis];
    resort(axis);
  }
  PairChanges changes;
  for (const auto& [key, was] : changed_) {
    const bool now = overlapping_.count(key) > 0;
    if (now && !was) changes.added.push_back(pair_of(key));
    if (!now && was) changes.removed.push_back(pair_of(key));
  }
  changed_.clear();
  std::sort(changes.added.begin(), changes.added.end());
  std::sort(changes.removed.begin(), changes.removed.end());
  return changes;
}

std::vector<ObjectPair> SweepAndPrune::pairs() const {
  std::vector<ObjectPair> out;
  out.reserve(overlapping_.size());
  for (std::uint64_t key : overlapping_) out.push_back(pair_of(key));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace cc
