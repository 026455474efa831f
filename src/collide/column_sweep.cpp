#include "collide/column_sweep.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

namespace cc {
namespace {

// Column numbers are clamped to [-kLimit, kLimit], which keeps the map monotone and the key
// of a column in 64 bits.
constexpr double kLimit = 0x1p30;
// The side of a column, in median box extents (before rounding up to a power of two).
constexpr double kSideInExtents = 1;
// How many entries ahead resort_and_sweep() asks for an entry's box.
constexpr std::size_t kAhead = 16;

ObjectPair ordered(ObjectId a, ObjectId b) { return a < b ? ObjectPair{a, b} : ObjectPair{b, a}; }

std::uint64_t column_key(std::int32_t y, std::int32_t z) {
  const auto offset = static_cast<std::int64_t>(kLimit);
  return (static_cast<std::uint64_t>(y + offset) << 32) | static_cast<std::uint64_t>(z + offset);
}

}  // namespace

// The order of the array: by column, then by lower x bound.
bool ColumnSweep::before(const Entry& a, const Entry& b) {
  if (a.column != b.column) return a.column < b.column;
  return a.lo_x < b.lo_x;
}

// floor(v / side), clamped: monotone in v (a scaling by a power of two, rounded, then floor).
std::int32_t ColumnSweep::column_of(double v) const {
  const double t = std::clamp(v * scale_, -kLimit, kLimit);
  const auto truncated = static_cast<std::int32_t>(t);
  return truncated - (t < truncated);  // floor
}

ColumnSweep::Span ColumnSweep::span_of(const Aabb& box) const {
  const Span s{column_of(box.lo.y), column_of(box.hi.y), column_of(box.lo.z), column_of(box.hi.z)};
  const std::int64_t count = (std::int64_t{s.y1} - s.y0 + 1) * (std::int64_t{s.z1} - s.z0 + 1);
  return count > kMaxColumns ? kOutside : s;
}

ObjectId ColumnSweep::add(const Aabb& box) {
  const auto id = static_cast<ObjectId>(boxes_.size());
  require_valid_box(box, "ColumnSweep::add", id);
  boxes_.push_back(box);
  spans_.push_back(kNone);
  alive_.push_back(true);
  ++live_;
  return id;
}

void ColumnSweep::move(ObjectId id, const Aabb& box) {
  if (id >= boxes_.size() || !alive_[id]) throw std::invalid_argument("ColumnSweep::move: no object " + std::to_string(id));
  require_valid_box(box, "ColumnSweep::move", id);
  boxes_[id] = box;
}

void ColumnSweep::remove(ObjectId id) {
  if (id >= boxes_.size() || !alive_[id]) throw std::invalid_argument("ColumnSweep::remove: no object " + std::to_string(id));
  alive_[id] = false;
  --live_;
  auto kept = pairs_.begin();
  for (const ObjectPair& p : pairs_) {
    if (p.first == id || p.second == id) {
      removed_since_.push_back(p);
    } else {
      *kept++ = p;
    }
  }
  pairs_.erase(kept, pairs_.end());
}

// The side: the power of two at or above kSideInExtents times the median of the boxes' larger
// extent across the columns (finite ones; 1 if there are none or the median is 0). If it
// changes, every box enters its columns again.
void ColumnSweep::choose_side() {
  std::vector<double> extents;
  for (ObjectId id = 0; id < boxes_.size(); ++id) {
    const Aabb& b = boxes_[id];
    const double e = std::max(b.hi.y - b.lo.y, b.hi.z - b.lo.z);
    if (alive_[id] && std::isfinite(e)) extents.push_back(e);
  }
  int exponent = 0;
  if (!extents.empty()) {
    const auto middle = extents.begin() + static_cast<std::ptrdiff_t>(extents.size() / 2);
    std::nth_element(extents.begin(), middle, extents.end());
    const double wanted = kSideInExtents * *middle;
    if (wanted > 0 && std::isfinite(wanted)) {
      const double fraction = std::frexp(wanted, &exponent);  // wanted = fraction * 2^exponent
      if (fraction == 0.5) --exponent;                        // wanted is a power of two
      exponent = std::clamp(exponent, -1000, 1000);
    }
  }
  live_at_choice_ = live_;
  if (std::ldexp(1.0, exponent) == side_) return;
  side_ = std::ldexp(1.0, exponent);
  scale_ = std::ldexp(1.0, -exponent);
  std::fill(spans_.begin(), spans_.end(), kNone);
  entries_.clear();
}

// The entries of the boxes entering columns (or entering them again), sorted.
void ColumnSweep::make_fresh() {
  fresh_.clear();
  for (ObjectId id : entering_) {
    const Span s = spans_[id];
    for (std::int32_t y = s.y0; y <= s.y1; ++y) {
      for (std::int32_t z = s.z0; z <= s.z1; ++z) {
        fresh_.push_back({column_key(y, z), boxes_[id].lo.x, id, static_cast<std::uint8_t>((y == s.y0) | (z == s.z0) << 1)});
      }
    }
  }
  std::sort(fresh_.begin(), fresh_.end(), before);
}

// One pass over the array: the entries of boxes leaving their columns are dropped, the others
// get their boxes' current lower x bounds, the fresh entries are merged in, and each entry is
// sorted into place by insertion (O(entries + swaps)). Kept entries keep their columns and the
// array was sorted by column, so a column is complete when the pass reaches the next one: it is
// swept then, while it is in the cache.
void ColumnSweep::resort_and_sweep() {
  found_count_ = 0;
  merged_.resize(entries_.size() + fresh_.size());
  std::size_t size = 0, column_begin = 0, next_fresh = 0;
  const auto place = [&](const Entry& e) {
    if (size > column_begin && e.column != merged_[column_begin].column) {
      sweep_column(column_begin, size);
      column_begin = size;
    }
    std::size_t j = size++;
    for (; j > column_begin && before(e, merged_[j - 1]); --j) {
      merged_[j] = merged_[j - 1];
      ++swaps_;
    }
    merged_[j] = e;
  };
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    // The boxes are read in column order, at random in memory: fetching the box kAhead entries
    // on while this one is placed overlaps the cache misses (a hint: no effect on the answer).
    if (k + kAhead < entries_.size()) {
      const Aabb& ahead = boxes_[entries_[k + kAhead].id];
      __builtin_prefetch(&ahead.lo.x);
      __builtin_prefetch(&ahead.hi.z);  // a box may straddle two cache lines
    }
    Entry e = entries_[k];
    if (leaving_[e.id]) continue;
    e.lo_x = boxes_[e.id].lo.x;
    while (next_fresh < fresh_.size() && before(fresh_[next_fresh], e)) place(fresh_[next_fresh++]);
    place(e);
  }
  while (next_fresh < fresh_.size()) place(fresh_[next_fresh++]);
  sweep_column(column_begin, size);
  merged_.resize(size);
  entries_.swap(merged_);
  found_.resize(found_count_);
  for (ObjectId g : outside_) {
    for (ObjectId h = 0; h < boxes_.size(); ++h) {
      if (h == g || !alive_[h] || (spans_[h] == kOutside && h < g)) continue;  // a pair of two outside: once
      if (test_aabb_aabb(boxes_[g], boxes_[h])) found_.push_back(ordered(g, h));
    }
  }
}

// The overlapping pairs of one column's entries [begin, end) of merged_, those whose lowest
// common column it is, into found_. The entries after a, up to the first whose lower x bound
// passes a's upper one, are those that overlap a along x (a's lower bound is at most theirs): y
// and z decide. The lowest common column of two boxes is the one where each coordinate is the
// first column of one of them (the column map is monotone, so the boxes' first common column
// along y is the larger of their first columns): the first-column flags of the two entries
// together hold both axes.
void ColumnSweep::sweep_column(std::size_t begin, std::size_t end) {
  std::size_t count = found_count_;
  for (std::size_t i = begin; i < end; ++i) {
    // Room for a pair with every later entry, so that the loop below needs no checks.
    if (found_.size() < count + (end - i)) found_.resize(std::max(2 * found_.size(), count + (end - i)));
    const Entry& a = merged_[i];
    const Aabb& box_a = boxes_[a.id];
    for (std::size_t j = i + 1; j < end && merged_[j].lo_x <= box_a.hi.x; ++j) {
      const Entry& b = merged_[j];  // branch-free: the pair is written, and kept if it counts
      const Aabb& box_b = boxes_[b.id];
      const bool lowest_common = (a.first | b.first) == kFirstBoth;
      const bool meet = (box_b.lo.y <= box_a.hi.y) & (box_a.lo.y <= box_b.hi.y) & (box_b.lo.z <= box_a.hi.z) &
                        (box_a.lo.z <= box_b.hi.z);
      found_[count] = ordered(a.id, b.id);
      count += lowest_common & meet;
    }
  }
  found_count_ = count;
}

// found_ sorted into now_: by counting on the first id, then each first id's few pairs by the
// second.
void ColumnSweep::sort_found() {
  ends_.assign(boxes_.size() + 1, 0);
  for (const ObjectPair& p : found_) ++ends_[p.first + 1];
  for (std::size_t i = 1; i < ends_.size(); ++i) ends_[i] += ends_[i - 1];
  now_.resize(found_.size());
  for (const ObjectPair& p : found_) now_[ends_[p.first]++] = p;  // ends_[a]: the end of a's pairs
  for (std::size_t a = 0, begin = 0; a < boxes_.size(); begin = ends_[a++]) {
    if (ends_[a] - begin > 1) std::sort(now_.begin() + static_cast<std::ptrdiff_t>(begin), now_.begin() + static_cast<std::ptrdiff_t>(ends_[a]));
  }
}

PairChanges ColumnSweep::update() {
  // The side is chosen again when the number of boxes has doubled or halved since, or when
  // many boxes were too big for their columns at the last update.
  if (side_ == 0 || live_ > 2 * live_at_choice_ || 2 * live_ < live_at_choice_ || 4 * outside_.size() > live_ + 16) {
    choose_side();
  }
  leaving_.assign(boxes_.size(), 0);
  entering_.clear();
  outside_.clear();
  for (ObjectId id = 0; id < boxes_.size(); ++id) {
    const Span s = alive_[id] ? span_of(boxes_[id]) : kNone;
    if (s == kOutside) outside_.push_back(id);
    if (s == spans_[id]) continue;
    leaving_[id] = 1;
    spans_[id] = s;
    if (s != kOutside && s != kNone) entering_.push_back(id);
  }
  make_fresh();
  resort_and_sweep();
  sort_found();

  PairChanges changes;
  std::set_difference(now_.begin(), now_.end(), pairs_.begin(), pairs_.end(), std::back_inserter(changes.added));
  std::set_difference(pairs_.begin(), pairs_.end(), now_.begin(), now_.end(), std::back_inserter(changes.removed));
  if (!removed_since_.empty()) {
    std::sort(removed_since_.begin(), removed_since_.end());
    std::vector<ObjectPair> removed;
    std::merge(changes.removed.begin(), changes.removed.end(), removed_since_.begin(), removed_since_.end(),
               std::back_inserter(removed));
    changes.removed.swap(removed);
    removed_since_.clear();
  }
  pairs_.swap(now_);
  return changes;
}

}  // namespace cc
