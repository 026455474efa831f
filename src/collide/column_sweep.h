// Sweep-and-prune in columns: the first level of collision detection among many moving objects,
// with work per frame that grows like the number of objects.
#pragma once

#include <cstdint>
#include <vector>

#include "collide/aabb.h"
#include "collide/sweep_and_prune.h"

namespace cc {

/// The overlapping pairs of a set of boxes that move a little from frame to frame, as
/// SweepAndPrune finds them, in O(n + k) per frame on a scene of bounded density (n boxes, k
/// pairs), where SweepAndPrune's endpoint swaps grow like n^(5/3) in three dimensions. The plane
/// of y and z is cut into square columns whose side is a power of two (about the boxes' median
/// extent; chosen again when the number of boxes has doubled or halved, or many are too big for
/// their columns). A box is entered in every column it overlaps; the entries live in one flat
/// array sorted by column, then by lower x bound. update() makes one pass over the array: it
/// re-sorts it by insertion (boxes that change columns leave it and are merged in again), and
/// sweeps each column along x as soon as it is complete, reporting a pair only in the two
/// boxes' lowest common column, so once. A box spanning more than kMaxColumns columns (a huge
/// or unbounded one) is kept outside them and tested against every box. The frame's pairs are
/// sorted by counting and compared with the last frame's for the changes.
///  - Closed boxes: boxes that touch (equal bounds) overlap, as test_aabb_aabb says. Zero-extent
///    boxes take part.
///  - Exact: the pairs are those of test_aabb_aabb on the current boxes. The columns only decide
///    which pairs are compared: a box's columns come from a monotone map of its bounds (a scaling
///    by a power of two, floor, clamping), so two boxes that share a point share a column.
///  - Domain: boxes with lo <= hi on every axis and no NaN (infinite bounds are fine); add()
///    and move() throw std::invalid_argument otherwise, naming the box.
class ColumnSweep {
 public:
  /// A box spanning more columns than this is tested against every box instead.
  static constexpr std::int64_t kMaxColumns = 16;

  /// Adds a box, overlapping from the next update() on; returns its id (ids are not reused).
  ObjectId add(const Aabb& box);
  /// Removes an object at once; its pairs are reported as removed by the next update().
  void remove(ObjectId id);
  /// Gives an object its box for the next update().
  void move(ObjectId id, const Aabb& box);
  /// Re-sorts the columns, sweeps them, and returns the pairs that changed since the last
  /// update(): each list sorted; a pair that started and stopped again in between is in neither.
  PairChanges update();

  /// The pairs overlapping as of the last update() (and removals since), sorted.
  const std::vector<ObjectPair>& pairs() const { return pairs_; }
  /// The number of live objects.
  std::size_t size() const { return live_; }
  /// Swaps made by the insertion sorts so far (the work that coherence saves).
  std::uint64_t swaps() const { return swaps_; }
  /// The side of a column as of the last update() (0 before the first).
  double column_side() const { return side_; }
  /// Column entries and boxes kept outside the columns, as of the last update().
  std::size_t column_entries() const { return entries_.size(); }
  std::size_t boxes_outside_columns() const { return outside_.size(); }

 private:
  // The columns a box overlaps: [y0, y1] x [z0, z1] in column numbers; `outside` for a box
  // spanning too many, `none` for a box not entered yet.
  struct Span {
    std::int32_t y0, y1, z0, z1;
    friend bool operator==(const Span&, const Span&) = default;
  };
  static constexpr Span kNone{1, 0, 1, 0};
  static constexpr Span kOutside{1, 0, 0, 1};
  // A box in one of its columns, with a copy of its lower x bound (the sort key).
  struct Entry {
    std::uint64_t column;
    double lo_x;
    ObjectId id;
    std::uint8_t first;  // bit 0: this is the box's first column along y; bit 1: along z
  };
  static constexpr std::uint8_t kFirstBoth = 3;
  static bool before(const Entry& a, const Entry& b);
  std::int32_t column_of(double v) const;
  Span span_of(const Aabb& box) const;
  void choose_side();
  void make_fresh();
  void resort_and_sweep();
  void sweep_column(std::size_t begin, std::size_t end);
  void sort_found();

  std::vector<Aabb> boxes_;
  std::vector<Span> spans_;  // as of the last update
  std::vector<bool> alive_;
  std::size_t live_ = 0;
  double side_ = 0, scale_ = 0;  // column side and its inverse (powers of two)
  std::size_t live_at_choice_ = 0;
  std::vector<Entry> entries_;
  std::vector<ObjectId> outside_;
  std::vector<ObjectPair> pairs_;          // as of the last update, without removed objects
  std::vector<ObjectPair> removed_since_;  // pairs of objects removed since the last update
  std::uint64_t swaps_ = 0;
  // Scratch of update(), kept to keep its capacity.
  std::vector<char> leaving_;
  std::vector<ObjectId> entering_;
  std::vector<Entry> fresh_, merged_;
  std::vector<ObjectPair> found_, now_;
  std::size_t found_count_ = 0;
  std::vector<std::uint32_t> ends_;
};

}  // namespace cc
