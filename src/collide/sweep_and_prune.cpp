#include "collide/sweep_and_prune.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

#include "collide/box_pairs.h"

namespace cc {
namespace {

std::uint64_t key_of(ObjectId a, ObjectId b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}
ObjectPair pair_of(std::uint64_t key) { return {static_cast<ObjectId>(key >> 32), static_cast<ObjectId>(key & 0xffffffffu)}; }

// The settled box of an object added since the last update: it overlaps nothing.
constexpr Aabb kNoBox{{NAN, NAN, NAN}, {NAN, NAN, NAN}};

}  // namespace

void require_valid_box(const Aabb& box, const char* who, ObjectId id) {
  for (int k = 0; k < 3; ++k) {
    if (std::isnan(box.lo[k]) || std::isnan(box.hi[k]) || box.lo[k] > box.hi[k]) {
      throw std::invalid_argument(std::string(who) + ": box of object " + std::to_string(id) +
                                  " has a NaN or lo > hi on axis " + "xyz"[k]);
    }
  }
}

// The order of the lists: by value, lower endpoints before upper ones at equal values (so that
// touching boxes overlap).
bool SweepAndPrune::before(const Endpoint& a, const Endpoint& b) {
  if (a.value != b.value) return a.value < b.value;
  return !a.upper && b.upper;
}

ObjectId SweepAndPrune::add(const Aabb& box) {
  const auto id = static_cast<ObjectId>(boxes_.size());
  require_valid_box(box, "SweepAndPrune::add", id);
  boxes_.push_back(box);
  settled_.push_back(kNoBox);
  alive_.push_back(true);
  ++live_;
  ++added_since_update_;
  // Both endpoints go to the end of each list at +inf, after every other endpoint, and reach
  // their places at the next update(), testing the boxes whose upper endpoints they pass.
  for (auto& list : axes_) {
    list.push_back({INFINITY, id, false});
    list.push_back({INFINITY, id, true});
  }
  return id;
}

void SweepAndPrune::move(ObjectId id, const Aabb& box) {
  if (id >= boxes_.size() || !alive_[id]) throw std::invalid_argument("SweepAndPrune::move: no object " + std::to_string(id));
  require_valid_box(box, "SweepAndPrune::move", id);
  boxes_[id] = box;
}

void SweepAndPrune::remove(ObjectId id) {
  if (id >= boxes_.size() || !alive_[id]) throw std::invalid_argument("SweepAndPrune::remove: no object " + std::to_string(id));
  for (auto& list : axes_) {  // its two endpoints to the end of each list, then dropped
    std::stable_partition(list.begin(), list.end(), [id](const Endpoint& e) { return e.id != id; });
    list.resize(list.size() - 2);
  }
  std::vector<std::uint64_t> gone;
  for (std::uint64_t key : overlapping_) {
    if (pair_of(key).first == id || pair_of(key).second == id) gone.push_back(key);
  }
  for (std::uint64_t key : gone) set_overlap(key, false);
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

// `moving_left` now sorts before `moved_right`, which sorted before it. Each pair of endpoints
// swaps at most once in a re-sort, and only if their order changed: a pair whose lower endpoint
// passed an upper one overlaps on this axis now, one whose upper endpoint passed a lower one
// does not.
void SweepAndPrune::flip(const Endpoint& moving_left, const Endpoint& moved_right) {
  if (moving_left.upper == moved_right.upper || moving_left.id == moved_right.id) return;
  const ObjectId a = moving_left.id, b = moved_right.id;
  if (!moving_left.upper) {  // they may start to overlap: the current boxes decide
    if (test_aabb_aabb(boxes_[a], boxes_[b])) set_overlap(key_of(a, b), true);
  } else if (test_aabb_aabb(settled_[a], settled_[b])) {  // they overlapped and no longer do
    set_overlap(key_of(a, b), false);
  }
}

void SweepAndPrune::resort(int axis) {
  auto& list = axes_[axis];
  for (std::size_t i = 1; i < list.size(); ++i) {
    for (std::size_t j = i; j > 0 && before(list[j], list[j - 1]); --j) {
      flip(list[j], list[j - 1]);
      std::swap(list[j], list[j - 1]);
      ++swaps_;
    }
  }
}

// Many new boxes would each travel far through the lists: sort them from scratch instead and
// take the pairs from a sweep, recording how they differ from the last update's.
void SweepAndPrune::rebuild() {
  for (auto& list : axes_) std::sort(list.begin(), list.end(), before);
  std::vector<Aabb> present(boxes_.size(), kNoBox);
  for (ObjectId id = 0; id < boxes_.size(); ++id) {
    if (alive_[id]) present[id] = boxes_[id];
  }
  std::vector<std::uint64_t> now, was(overlapping_.begin(), overlapping_.end());
  for (const auto& [a, b] : sort_and_sweep(present)) now.push_back(key_of(a, b));
  std::sort(was.begin(), was.end());
  std::vector<std::uint64_t> started, stopped;
  std::set_difference(now.begin(), now.end(), was.begin(), was.end(), std::back_inserter(started));
  std::set_difference(was.begin(), was.end(), now.begin(), now.end(), std::back_inserter(stopped));
  for (std::uint64_t key : started) set_overlap(key, true);
  for (std::uint64_t key : stopped) set_overlap(key, false);
}

PairChanges SweepAndPrune::update() {
  for (int axis = 0; axis < 3; ++axis) {
    for (Endpoint& e : axes_[axis]) e.value = e.upper ? boxes_[e.id].hi[axis] : boxes_[e.id].lo[axis];
  }
  if (added_since_update_ >= kBulkAdditions) {
    rebuild();
  } else {
    for (int axis = 0; axis < 3; ++axis) resort(axis);
  }
  added_since_update_ = 0;
  settled_ = boxes_;
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
