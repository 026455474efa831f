// Properties of the first level: sweep-and-prune in columns, incremental sweep-and-prune, the
// full re-sort and brute force give the same pairs on every frame, through moves, insertions and
// removals, and the pairs each frame reports as added and removed are exactly the differences
// between the last frame's set and this one's. Boxes sit on a coarse grid of halves, so that
// equal endpoints, touching boxes, zero-extent boxes, identical boxes and boxes inside others
// come up all the time, and bounds on column boundaries too (the columns' sides are powers of
// two); some are unbounded. The property counts them, and the boxes in several columns and
// outside the columns.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "collide/box_pairs.h"
#include "collide/column_sweep.h"
#include "properties/property.h"

namespace cc::test {
namespace {

using harness::Choices;

double grid_value(Choices& c) { return 0.5 * (static_cast<double>(c.draw(17)) - 8); }

Aabb draw_box(Choices& c, const std::vector<Aabb>& others) {
  if (!others.empty() && c.chance(15)) return others[c.draw(others.size())];  // identical
  Aabb b;
  for (int k = 0; k < 3; ++k) {
    const double a = grid_value(c), z = c.chance(20) ? a : grid_value(c);  // zero extent sometimes
    b.lo[k] = std::min(a, z), b.hi[k] = std::max(a, z);
  }
  if (c.chance(4)) (c.chance(50) ? b.lo : b.hi)[static_cast<int>(c.draw(3))] = c.chance(50) ? -INFINITY : INFINITY;
  for (int k = 0; k < 3; ++k) {
    if (b.lo[k] > b.hi[k]) std::swap(b.lo[k], b.hi[k]);  // an infinity on the wrong side
  }
  return b;
}

struct Seen {
  int frames = 0, touching = 0, zero_extent = 0, identical = 0, nested = 0, removals = 0, unbounded = 0;
  std::size_t in_several_columns = 0, outside_columns = 0;
  void count(const std::vector<Aabb>& boxes, const std::vector<ObjectPair>& pairs) {
    ++frames;
    for (const auto& [i, j] : pairs) {
      const Aabb &a = boxes[i], &b = boxes[j];
      bool touch = false, inside = true;
      for (int k = 0; k < 3; ++k) {
        touch = touch || a.hi[k] == b.lo[k] || b.hi[k] == a.lo[k];
        inside = inside && a.lo[k] <= b.lo[k] && b.hi[k] <= a.hi[k];
      }
      touching += touch;
      identical += a == b;
      nested += inside && !(a == b);
    }
    for (const Aabb& b : boxes) {
      zero_extent += b.lo.x == b.hi.x || b.lo.y == b.hi.y || b.lo.z == b.hi.z;
      unbounded += !std::isfinite(b.hi.x - b.lo.x) || !std::isfinite(b.hi.y - b.lo.y) || !std::isfinite(b.hi.z - b.lo.z);
    }
  }
  void count(const ColumnSweep& columns) {
    outside_columns += columns.boxes_outside_columns();
    in_several_columns += columns.column_entries() - std::min(columns.column_entries(), columns.size() - columns.boxes_outside_columns());
  }
};

TEST(BroadphaseProperties, ColumnsIncrementalResortAndBruteForceAgreeOnEveryFrame) {
  Seen seen;
  const bool passed = check_property_with_choices("sweep-and-prune agrees with brute force", 300, [&](Choices& c) {
    ColumnSweep columns;
    SweepAndPrune sap;
    std::vector<Aabb> boxes;       // the live boxes, in slots
    std::vector<ObjectId> ids;     // their ids in both broadphases (they count alike)
    const auto add = [&](const Aabb& box) {
      boxes.push_back(box);
      ids.push_back(sap.add(box));
      RC_ASSERT(columns.add(box) == ids.back());
    };
    const std::size_t n = 1 + c.draw(30);
    for (std::size_t i = 0; i < n; ++i) add(draw_box(c, boxes));
    std::vector<ObjectPair> last;
    for (int frame = 0, frames = 1 + static_cast<int>(c.draw(8)); frame < frames; ++frame) {
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (!c.chance(40)) continue;
        const Vec3 step{0.5 * (static_cast<double>(c.draw(3)) - 1), 0.5 * (static_cast<double>(c.draw(3)) - 1),
                        0.5 * (static_cast<double>(c.draw(3)) - 1)};
        boxes[i] = {boxes[i].lo + step, boxes[i].hi + step};
        sap.move(ids[i], boxes[i]);
        columns.move(ids[i], boxes[i]);
      }
      if (!boxes.empty() && c.chance(30)) {  // one leaves
        const std::size_t i = c.draw(boxes.size());
        sap.remove(ids[i]);
        columns.remove(ids[i]);
        boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(i));
        ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(i));
        ++seen.removals;
      }
      if (c.chance(30)) add(draw_box(c, boxes));  // one arrives
      const PairChanges changes = sap.update();
      const PairChanges column_changes = columns.update();
      const std::vector<ObjectPair> brute = box_pairs_brute_force(boxes);
      RC_ASSERT(sort_and_sweep(boxes) == brute);
      std::vector<ObjectPair> expected;
      for (const auto& [i, j] : brute) expected.emplace_back(std::min(ids[i], ids[j]), std::max(ids[i], ids[j]));
      std::sort(expected.begin(), expected.end());
      RC_ASSERT(sap.pairs() == expected);
      RC_ASSERT(columns.pairs() == expected);
      // The changes are exactly the differences between the two frames' sets: a pair that
      // started and stopped again between the updates (or stopped and started) is in neither.
      std::vector<ObjectPair> started, stopped;
      std::set_difference(expected.begin(), expected.end(), last.begin(), last.end(), std::back_inserter(started));
      std::set_difference(last.begin(), last.end(), expected.begin(), expected.end(), std::back_inserter(stopped));
      RC_ASSERT(changes.added == started);
      RC_ASSERT(changes.removed == stopped);
      RC_ASSERT(column_changes.added == started);
      RC_ASSERT(column_changes.removed == stopped);
      std::vector<ObjectPair> replayed;
      for (const ObjectPair& p : last) {
        if (!std::binary_search(changes.removed.begin(), changes.removed.end(), p)) replayed.push_back(p);
      }
      replayed.insert(replayed.end(), changes.added.begin(), changes.added.end());
      std::sort(replayed.begin(), replayed.end());
      RC_ASSERT(replayed == expected);
      last = expected;
      seen.count(boxes, brute);
      seen.count(columns);
    }
  });
  EXPECT_TRUE(passed);
  std::printf("%d frames: %d touching pairs, %d zero-extent boxes, %d unbounded boxes, %d identical pairs, %d nested pairs, "
              "%d removals, %zu column entries beyond a box's first, %zu boxes outside the columns\n",
              seen.frames, seen.touching, seen.zero_extent, seen.unbounded, seen.identical, seen.nested, seen.removals,
              seen.in_several_columns, seen.outside_columns);
  EXPECT_GT(seen.touching, 100);
  EXPECT_GT(seen.zero_extent, 100);
  EXPECT_GT(seen.identical, 50);
  EXPECT_GT(seen.nested, 50);
  EXPECT_GT(seen.removals, 50);
  EXPECT_GT(seen.unbounded, 100);
  EXPECT_GT(seen.in_several_columns, 1000u);
  EXPECT_GT(seen.outside_columns, 100u);
}

}  // namespace
}  // namespace cc::test
