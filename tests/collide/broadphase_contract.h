// The contract both incremental broadphases (SweepAndPrune, ColumnSweep) keep, as a
// type-parameterised test suite their own test files instantiate: pairs from the first update,
// touching boxes, pairs that part and meet again, removals, the domain check; and the check of
// one frame against brute force that their coherent-motion tests share.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "collide/box_pairs.h"

namespace cc::test {

inline Aabb cube(double x, double y, double z, double half = 0.5) {
  return {{x - half, y - half, z - half}, {x + half, y + half, z + half}};
}

/// After an update: the broadphase's pairs are brute force's on the boxes (ids[i] is box i's
/// id), and the pairs before it plus the changes' added minus their removed give them too.
template <class Broadphase>
void expect_brute_force_frame(const Broadphase& broadphase, const std::vector<Aabb>& boxes,
                              const std::vector<ObjectId>& ids, const std::vector<ObjectPair>& before,
                              const PairChanges& changes, int frame) {
  std::vector<ObjectPair> expected;
  for (const auto& [i, j] : box_pairs_brute_force(boxes)) expected.emplace_back(std::min(ids[i], ids[j]), std::max(ids[i], ids[j]));
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(broadphase.pairs(), expected) << "frame " << frame;
  std::vector<ObjectPair> replayed;
  for (const ObjectPair& p : before) {
    if (!std::binary_search(changes.removed.begin(), changes.removed.end(), p)) replayed.push_back(p);
  }
  replayed.insert(replayed.end(), changes.added.begin(), changes.added.end());
  std::sort(replayed.begin(), replayed.end());
  ASSERT_EQ(replayed, expected) << "frame " << frame;
}

template <class Broadphase>
class BroadphaseContract : public ::testing::Test {};
TYPED_TEST_SUITE_P(BroadphaseContract);

TYPED_TEST_P(BroadphaseContract, ReportsPairsFromTheFirstUpdate) {
  TypeParam broadphase;
  const ObjectId a = broadphase.add(cube(0, 0, 0)), b = broadphase.add(cube(0.5, 0.5, 0.5)), c = broadphase.add(cube(5, 0, 0));
  EXPECT_TRUE(broadphase.pairs().empty());  // nothing before the first update
  const PairChanges changes = broadphase.update();
  EXPECT_EQ(changes.added, (std::vector<ObjectPair>{{a, b}}));
  EXPECT_TRUE(changes.removed.empty());
  EXPECT_EQ(broadphase.pairs(), (std::vector<ObjectPair>{{a, b}}));
  EXPECT_EQ(broadphase.size(), 3u);
  (void)c;
}

TYPED_TEST_P(BroadphaseContract, TouchingBoxesOverlapOnEveryAxis) {
  TypeParam broadphase;
  broadphase.add(cube(0, 0, 0));
  broadphase.add(cube(1, 0, 0));  // shares the face x = 0.5
  broadphase.add(cube(1, 1, 1));  // shares only a corner with the first
  broadphase.add({{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}});  // a point on that corner
  broadphase.update();
  EXPECT_EQ(broadphase.pairs(), (std::vector<ObjectPair>{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}));
}

TYPED_TEST_P(BroadphaseContract, MovingApartAndBackFlipsThePair) {
  TypeParam broadphase;
  const ObjectId a = broadphase.add(cube(0, 0, 0)), b = broadphase.add(cube(0.75, 0, 0));
  broadphase.update();
  broadphase.move(b, cube(1.5, 0, 0));
  PairChanges c = broadphase.update();
  EXPECT_EQ(c.removed, (std::vector<ObjectPair>{{a, b}}));
  EXPECT_TRUE(broadphase.pairs().empty());
  broadphase.move(b, cube(1, 0, 0));  // touching again
  c = broadphase.update();
  EXPECT_EQ(c.added, (std::vector<ObjectPair>{{a, b}}));
  // Apart along y while still overlapping along x and z: one axis is enough to part them.
  broadphase.move(b, cube(0.25, 3, 0));
  c = broadphase.update();
  EXPECT_EQ(c.removed, (std::vector<ObjectPair>{{a, b}}));
  // Both far from where they were, meeting again there.
  broadphase.move(a, cube(0, 7.5, -4));
  broadphase.move(b, cube(0.5, 8.25, -4.5));
  c = broadphase.update();
  EXPECT_EQ(c.added, (std::vector<ObjectPair>{{a, b}}));
  EXPECT_TRUE(c.removed.empty());
}

TYPED_TEST_P(BroadphaseContract, RemovalReportsThePairsAndForgetsTheObject) {
  TypeParam broadphase;
  const ObjectId a = broadphase.add(cube(0, 0, 0)), b = broadphase.add(cube(0.5, 0, 0)), c = broadphase.add(cube(0, 0.5, 0));
  broadphase.update();
  ASSERT_EQ(broadphase.pairs().size(), 3u);
  broadphase.remove(b);
  EXPECT_EQ(broadphase.size(), 2u);
  EXPECT_EQ(broadphase.pairs(), (std::vector<ObjectPair>{{a, c}}));
  const PairChanges changes = broadphase.update();
  EXPECT_EQ(changes.removed, (std::vector<ObjectPair>{{a, b}, {b, c}}));
  EXPECT_TRUE(changes.added.empty());
  EXPECT_THROW(broadphase.move(b, cube(0, 0, 0)), std::invalid_argument);
  EXPECT_THROW(broadphase.remove(b), std::invalid_argument);
  EXPECT_THROW(broadphase.move(17, cube(0, 0, 0)), std::invalid_argument);
  // A new object gets a new id and meets the others.
  const ObjectId d = broadphase.add(cube(0, 0, 0));
  EXPECT_NE(d, b);
  EXPECT_EQ(broadphase.update().added, (std::vector<ObjectPair>{{a, d}, {c, d}}));
}

TYPED_TEST_P(BroadphaseContract, APairAddedAndRemovedBetweenUpdatesIsNeither) {
  TypeParam broadphase;
  const ObjectId a = broadphase.add(cube(0, 0, 0));
  broadphase.update();
  const ObjectId b = broadphase.add(cube(0, 0, 0));
  broadphase.update();  // (a, b) added
  broadphase.remove(b);
  const ObjectId c = broadphase.add(cube(9, 9, 9));
  const PairChanges changes = broadphase.update();
  EXPECT_EQ(changes.removed, (std::vector<ObjectPair>{{a, b}}));
  EXPECT_TRUE(changes.added.empty());
  (void)c;
}

TYPED_TEST_P(BroadphaseContract, RefusesNanAndInvertedBoxes) {
  TypeParam broadphase;
  EXPECT_THROW(broadphase.add({{0, 0, 0}, {1, NAN, 1}}), std::invalid_argument);
  EXPECT_THROW(broadphase.add({{0, 2, 0}, {1, 1, 1}}), std::invalid_argument);
  const ObjectId a = broadphase.add({{-INFINITY, 0, 0}, {INFINITY, 1, 1}});  // unbounded is fine
  EXPECT_THROW(broadphase.move(a, {{0, 0, NAN}, {1, 1, 1}}), std::invalid_argument);
  const ObjectId b = broadphase.add(cube(1e300, 0.5, 0.5));
  broadphase.update();
  EXPECT_EQ(broadphase.pairs(), (std::vector<ObjectPair>{{a, b}}));
}

REGISTER_TYPED_TEST_SUITE_P(BroadphaseContract, ReportsPairsFromTheFirstUpdate, TouchingBoxesOverlapOnEveryAxis,
                            MovingApartAndBackFlipsThePair, RemovalReportsThePairsAndForgetsTheObject,
                            APairAddedAndRemovedBetweenUpdatesIsNeither, RefusesNanAndInvertedBoxes);

}  // namespace cc::test
