#include "collide/sweep_and_prune.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "collide/box_pairs.h"

namespace cc {
namespace {

Aabb cube(double x, double y, double z, double half = 0.5) {
  return {{x - half, y - half, z - half}, {x + half, y + half, z + half}};
}

TEST(SweepAndPrune, ReportsPairsFromTheFirstUpdate) {
  SweepAndPrune sap;
  const ObjectId a = sap.add(cube(0, 0, 0)), b = sap.add(cube(0.5, 0.5, 0.5)), c = sap.add(cube(5, 0, 0));
  EXPECT_TRUE(sap.pairs().empty());  // nothing before the first update
  const PairChanges changes = sap.update();
  EXPECT_EQ(changes.added, (std::vector<ObjectPair>{{a, b}}));
  EXPECT_TRUE(changes.removed.empty());
  EXPECT_EQ(sap.pairs(), (std::vector<ObjectPair>{{a, b}}));
  (void)c;
}

TEST(SweepAndPrune, TouchingBoxesOverlapOnEveryAxis) {
  SweepAndPrune sap;
  sap.add(cube(0, 0, 0));
  sap.add(cube(1, 0, 0));  // shares the face x = 0.5
  sap.add(cube(1, 1, 1));  // shares only a corner with the first
  sap.add({{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}});  // a point on that corner
  sap.update();
  EXPECT_EQ(sap.pairs(), (std::vector<ObjectPair>{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}));
}

TEST(SweepAndPrune, MovingApartAndBackFlipsThePair) {
  SweepAndPrune sap;
  const ObjectId a = sap.add(cube(0, 0, 0)), b = sap.add(cube(0.75, 0, 0));
  sap.update();
  sap.move(b, cube(1.5, 0, 0));
  PairChanges c = sap.update();
  EXPECT_EQ(c.removed, (std::vector<ObjectPair>{{a, b}}));
  EXPECT_TRUE(sap.pairs().empty());
  sap.move(b, cube(1, 0, 0));  // touching again
  c = sap.update();
  EXPECT_EQ(c.added, (std::vector<ObjectPair>{{a, b}}));
  // Apart along y while still overlapping along x and z: one axis is enough to part them.
  sap.move(b, cube(0.25, 3, 0));
  c = sap.update();
  EXPECT_EQ(c.removed, (std::vector<ObjectPair>{{a, b}}));
}

TEST(SweepAndPrune, RemovalReportsThePairsAndForgetsTheObject) {
  SweepAndPrune sap;
  const ObjectId a = sap.add(cube(0, 0, 0)), b = sap.add(cube(0.5, 0, 0)), c = sap.add(cube(0, 0.5, 0));
  sap.update();
  ASSERT_EQ(sap.pairs().size(), 3u);
  sap.remove(b);
  EXPECT_EQ(sap.size(), 2u);
  EXPECT_EQ(sap.pairs(), (std::vector<ObjectPair>{{a, c}}));
  const PairChanges changes = sap.update();
  EXPECT_EQ(changes.removed, (std::vector<ObjectPair>{{a, b}, {b, c}}));
  EXPECT_THROW(sap.move(b, cube(0, 0, 0)), std::invalid_argument);
  EXPECT_THROW(sap.remove(b), std::invalid_argument);
  // A new object gets a new id and meets the others.
  const ObjectId d = sap.add(cube(0, 0, 0));
  EXPECT_NE(d, b);
  EXPECT_EQ(sap.update().added, (std::vector<ObjectPair>{{a, d}, {c, d}}));
}

TEST(SweepAndPrune, APairAddedAndRemovedBetweenUpdatesIsNeither) {
  SweepAndPrune sap;
  const ObjectId a = sap.add(cube(0, 0, 0));
  sap.update();
  const ObjectId b = sap.add(cube(0, 0, 0));
  sap.update();  // (a, b) added
  sap.remove(b);
  const ObjectId c = sap.add(cube(9, 9, 9));
  const PairChanges changes = sap.update();
  EXPECT_EQ(changes.removed, (std::vector<ObjectPair>{{a, b}}));
  EXPECT_TRUE(changes.added.empty());
  (void)c;
}

TEST(SweepAndPrune, RefusesNanAndInvertedBoxes) {
  SweepAndPrune sap;
  EXPECT_THROW(sap.add({{0, 0, 0}, {1, NAN, 1}}), std::invalid_argument);
  EXPECT_THROW(sap.add({{0, 2, 0}, {1, 1, 1}}), std::invalid_argument);
  const ObjectId a = sap.add({{-INFINITY, 0, 0}, {INFINITY, 1, 1}});  // unbounded is fine
  EXPECT_THROW(sap.move(a, {{0, 0, NAN}, {1, 1, 1}}), std::invalid_argument);
  const ObjectId b = sap.add(cube(1e300, 0.5, 0.5));
  sap.update();
  EXPECT_EQ(sap.pairs(), (std::vector<ObjectPair>{{a, b}}));
}

// Coherent random motion with insertions and removals: the same pairs as brute force every
// frame, and far fewer swaps than a full sort would make. The first frame and frame 30 (40
// arrivals at once) take the bulk path, the others the insertion sort.
TEST(SweepAndPrune, AgreesWithBruteForceUnderCoherentMotion) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  SweepAndPrune sap;
  std::vector<ObjectId> ids;
  std::vector<Aabb> boxes;
  std::vector<Vec3> velocity;
  for (int i = 0; i < 200; ++i) {
    boxes.push_back(cube(20 * unit(random), 20 * unit(random), 20 * unit(random), 0.2 + unit(random)));
    velocity.push_back({unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5});
    ids.push_back(sap.add(boxes.back()));
  }
  for (int frame = 0; frame < 60; ++frame) {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const Vec3 step = 0.1 * velocity[i];
      boxes[i] = {boxes[i].lo + step, boxes[i].hi + step};
      sap.move(ids[i], boxes[i]);
    }
    if (frame % 10 == 5) {  // one leaves, one arrives
      sap.remove(ids[frame % ids.size()]);
      boxes[frame % ids.size()] = cube(10, 10, 10);
      ids[frame % ids.size()] = sap.add(boxes[frame % ids.size()]);
    }
    if (frame == 30) {  // a crowd arrives while one more leaves
      sap.remove(ids[7]);
      boxes[7] = cube(-50, -50, -50);
      ids[7] = sap.add(boxes[7]);
      for (int i = 0; i < 40; ++i) {
        boxes.push_back(cube(20 * unit(random), 20 * unit(random), 20 * unit(random), 0.2 + unit(random)));
        velocity.push_back({unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5});
        ids.push_back(sap.add(boxes.back()));
      }
    }
    const std::vector<ObjectPair> before = sap.pairs();
    const PairChanges changes = sap.update();
    std::vector<ObjectPair> expected;
    for (const auto& [i, j] : box_pairs_brute_force(boxes)) expected.emplace_back(std::min(ids[i], ids[j]), std::max(ids[i], ids[j]));
    std::sort(expected.begin(), expected.end());
    ASSERT_EQ(sap.pairs(), expected) << "frame " << frame;
    // before + added - removed = now
    std::vector<ObjectPair> replayed;
    for (const ObjectPair& p : before) {
      if (!std::binary_search(changes.removed.begin(), changes.removed.end(), p)) replayed.push_back(p);
    }
    replayed.insert(replayed.end(), changes.added.begin(), changes.added.end());
    std::sort(replayed.begin(), replayed.end());
    ASSERT_EQ(replayed, expected) << "frame " << frame;
  }
  EXPECT_LT(sap.swaps(), 60u * 200 * 20);  // coherence: a few swaps per box and frame
}

}  // namespace
}  // namespace cc
