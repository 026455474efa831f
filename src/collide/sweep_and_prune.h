// Sweep-and-prune with temporal coherence (Cohen, Lin, Manocha and Ponamgi, I-COLLIDE): the
// first level of collision detection among many moving objects.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "collide/aabb.h"

namespace cc {

using ObjectId = std::uint32_t;
/// Two objects, the smaller id first.
using ObjectPair = std::pair<ObjectId, ObjectId>;

/// The pairs that started and stopped overlapping between two updates, each sorted. A pair
/// that started and stopped again in between is in neither.
struct PairChanges {
  std::vector<ObjectPair> added, removed;
};

/// The broadphases' domain check: throws std::invalid_argument, naming `who` and the object,
/// unless the box has lo <= hi on every axis and no NaN (infinite bounds are fine).
void require_valid_box(const Aabb& box, const char* who, ObjectId id);

/// The overlapping pairs of a set of boxes that move a little from frame to frame. Per axis a
/// list of the boxes' endpoints is kept sorted; update() re-sorts it by insertion sort, which
/// costs O(n + swaps) on coherent motion. A swap that puts one box's lower endpoint before
/// another's upper endpoint may start an overlap: the two current boxes are tested on all three
/// axes and the pair is kept if they meet. A swap that puts an upper endpoint before a lower one
/// parts the pair on that axis: the pair is dropped if it overlapped at the last update. Only
/// overlapping pairs are stored, so a frame costs O(n + k + swaps), k the number of pairs that
/// overlap or change. After many additions (kBulkAdditions or more since the last update) the
/// lists are sorted from scratch and the pairs found by sort_and_sweep instead.
///  - Closed boxes: boxes that touch (equal endpoints) overlap, as test_aabb_aabb says; at equal
///    values lower endpoints sort before upper ones. Zero-extent boxes take part.
///  - Exact: only comparisons of the given bounds; the pairs are always those of
///    test_aabb_aabb on the current boxes.
///  - Domain: boxes with lo <= hi on every axis and no NaN (infinite bounds are fine); add()
///    and move() throw std::invalid_argument otherwise, naming the box.
class SweepAndPrune {
 public:
  /// Adds a box, overlapping from the next update() on; returns its id (ids are not reused).
  ObjectId add(const Aabb& box);
  /// Removes an object at once; its pairs are reported as removed by the next update().
  void remove(ObjectId id);
  /// Gives an object its box for the next update().
  void move(ObjectId id, const Aabb& box);
  /// Re-sorts the endpoint lists and returns the pairs that changed since the last update().
  PairChanges update();

  /// The pairs overlapping as of the last update() (and removals since), sorted.
  std::vector<ObjectPair> pairs() const;
  /// The number of live objects.
  std::size_t size() const { return live_; }
  /// Endpoint swaps made by all re-sorts so far (the work that coherence saves).
  std::uint64_t swaps() const { return swaps_; }

 private:
  struct Endpoint {
    double value;
    ObjectId id;
    bool upper;
  };
  static constexpr std::size_t kBulkAdditions = 32;
  static bool before(const Endpoint& a, const Endpoint& b);
  void resort(int axis);
  void rebuild();
  void flip(const Endpoint& moving_left, const Endpoint& moved_right);
  void set_overlap(std::uint64_t key, bool overlapping);

  std::vector<Aabb> boxes_;
  std::vector<Aabb> settled_;  // the boxes at the last update; NaN for objects added since
  std::vector<bool> alive_;
  std::size_t live_ = 0;
  std::size_t added_since_update_ = 0;
  std::vector<Endpoint> axes_[3];
  std::unordered_set<std::uint64_t> overlapping_;  // pairs overlapping (as of the last update)
  std::unordered_map<std::uint64_t, bool> changed_;  // pair -> overlapping at the last update
  std::uint64_t swaps_ = 0;
};

}  // namespace cc
