#include "collide/column_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "collide/broadphase_contract.h"

namespace cc::test {
namespace {

INSTANTIATE_TYPED_TEST_SUITE_P(ColumnSweep, BroadphaseContract, ::testing::Types<ColumnSweep>);

TEST(ColumnSweep, TheSideIsThePowerOfTwoAtOrAboveTheMedianExtent) {
  ColumnSweep sweep;
  EXPECT_EQ(sweep.column_side(), 0);
  for (int i = 0; i < 5; ++i) sweep.add(cube(10.0 * i, 0, 0, 1.5));  // extent 3
  sweep.add(cube(0, 50, 0, 40));
  sweep.update();
  EXPECT_EQ(sweep.column_side(), 4);
  // A box of extent 80 spans 21 x 21 columns of side 4: it is kept outside them.
  EXPECT_EQ(sweep.boxes_outside_columns(), 1u);
  EXPECT_EQ(sweep.column_entries(), 5u * 4);  // each cube of extent 3 spans 2 x 2 columns here
  ColumnSweep points;
  points.add({{1, 1, 1}, {1, 1, 1}});
  points.add({{1, 1, 1}, {1, 1, 1}});
  points.update();
  EXPECT_EQ(points.column_side(), 1);  // median extent 0
  EXPECT_EQ(points.pairs(), (std::vector<ObjectPair>{{0, 1}}));
}

// Unit cubes get columns of side 1: a cube [0, 1] spans columns 0 and 1 (its upper face lies on
// the boundary), so boxes that touch on a column boundary still share a column.
TEST(ColumnSweep, TouchingBoxesOverlapAlsoOnColumnBoundaries) {
  ColumnSweep sweep;
  sweep.add({{0, 0, 0}, {1, 1, 1}});
  sweep.add({{0, 1, 0}, {1, 2, 1}});  // shares the face y = 1, a column boundary
  sweep.add({{1, 1, 1}, {2, 2, 2}});  // shares only the corner (1, 1, 1) with the first
  sweep.add({{1, 1, 1}, {1, 1, 1}});  // a point on that corner
  sweep.add({{-1, -1, -1}, {-0.0, -0.0, -0.0}});  // touches the first at the origin (-0 == 0)
  sweep.update();
  ASSERT_EQ(sweep.column_side(), 1);
  EXPECT_EQ(sweep.pairs(), (std::vector<ObjectPair>{{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 3}, {2, 3}}));
}

TEST(ColumnSweep, APairSharingManyColumnsIsReportedOnce) {
  ColumnSweep sweep;
  for (int i = 0; i < 4; ++i) sweep.add(cube(0, 0, 0, 0.5));  // side 1
  const ObjectId big = sweep.add({{-1, -1.5, -1.5}, {1, 1.5, 1.5}});  // 4 x 4 columns
  const ObjectId other = sweep.add({{0, -1, -1}, {2, 1, 1}});         // 3 x 3 columns
  sweep.update();
  ASSERT_EQ(sweep.column_side(), 1);
  ASSERT_EQ(sweep.boxes_outside_columns(), 0u);
  EXPECT_EQ(sweep.column_entries(), 4u * 4 + 16 + 9);
  std::vector<ObjectPair> expected;
  for (ObjectId i = 0; i < 6; ++i) {
    for (ObjectId j = i + 1; j < 6; ++j) expected.emplace_back(i, j);
  }
  EXPECT_EQ(sweep.pairs(), expected);
  (void)big, (void)other;
}

TEST(ColumnSweep, ARemovedBoxLeavesItsColumns) {
  ColumnSweep sweep;
  const ObjectId a = sweep.add(cube(0, 0, 0)), b = sweep.add(cube(0.5, 0, 0));
  sweep.update();
  EXPECT_EQ(sweep.column_entries(), 2u * 4);  // each [-0.5, 0.5] in 2 x 2 columns of side 1
  sweep.remove(b);
  sweep.update();
  EXPECT_EQ(sweep.column_entries(), 4u);
  (void)a;
}

// Unbounded boxes, and boxes so far out that their column numbers are clamped, are still paired
// exactly: the clamped map is monotone, so far boxes share an edge column and the bounds decide.
TEST(ColumnSweep, UnboundedAndFarBoxesArePairedExactly) {
  ColumnSweep sweep;
  std::vector<Aabb> boxes = {
      {{-INFINITY, 0, 0}, {INFINITY, 1, 1}},    // a slab along x: fits one column
      {{0, -INFINITY, 0}, {1, INFINITY, 1}},    // unbounded along y: outside the columns
      {{0, 0, -INFINITY}, {1, 1, INFINITY}},    // unbounded along z: outside
      cube(1e300, 0.5, 0.5),                    // far along x, in the slab
      cube(0.5, 1e300, 0.5),                    // far along y: clamped column
      cube(0.5, 1e300 + 1e285, 0.5),            // farther, touching nothing
      {{0, 1e300, 0}, {1, 1e300, 1}},           // the far cube is flat at y = 1e300 (rounding): meets it
      cube(0.5, -1e300, 0.5),                   // far the other way
      {{0, 0, 0}, {0, 0, 0}},                   // a point where everything meets
      {{0, 0, 0}, {1, 1, 1}},
  };
  for (const Aabb& b : boxes) sweep.add(b);
  sweep.update();
  EXPECT_EQ(sweep.boxes_outside_columns(), 2u);
  EXPECT_EQ(sweep.pairs(), box_pairs_brute_force(boxes));
  EXPECT_GT(sweep.pairs().size(), 10u);
}

// Coherent random motion with insertions and removals: the same pairs as brute force every
// frame, boxes crossing columns, big boxes going in and out of the columns, and the side chosen
// again when a crowd of larger boxes arrives; far fewer swaps than a full sort would make.
TEST(ColumnSweep, AgreesWithBruteForceUnderCoherentMotion) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  ColumnSweep sweep;
  std::vector<ObjectId> ids;
  std::vector<Aabb> boxes;
  std::vector<Vec3> velocity;
  const auto arrive = [&](double spread, double size) {
    boxes.push_back(cube(spread * unit(random), spread * unit(random), spread * unit(random), size * (0.2 + unit(random))));
    velocity.push_back({unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5});
    ids.push_back(sweep.add(boxes.back()));
  };
  for (int i = 0; i < 200; ++i) arrive(20, 1);
  std::vector<double> sides;
  std::size_t most_outside = 0, changed_columns = 0;
  for (int frame = 0; frame < 60; ++frame) {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const Vec3 step = 0.1 * velocity[i];
      boxes[i] = {boxes[i].lo + step, boxes[i].hi + step};
      if (i % 50 == 4) boxes[i].hi = boxes[i].lo + (frame % 20 < 10 ? 1.5 : 1 / 1.5) * (boxes[i].hi - boxes[i].lo);  // grow, shrink
      sweep.move(ids[i], boxes[i]);
    }
    if (frame % 10 == 5) {  // one leaves, one arrives
      sweep.remove(ids[frame % ids.size()]);
      boxes[frame % ids.size()] = cube(10, 10, 10);
      ids[frame % ids.size()] = sweep.add(boxes[frame % ids.size()]);
    }
    if (frame == 30) {  // a crowd of larger boxes arrives while one more leaves
      sweep.remove(ids[7]);
      boxes[7] = cube(-50, -50, -50);
      ids[7] = sweep.add(boxes[7]);
      for (int i = 0; i < 250; ++i) arrive(30, 3);
    }
    const std::size_t entries_before = sweep.column_entries();
    const std::vector<ObjectPair> before = sweep.pairs();
    const PairChanges changes = sweep.update();
    changed_columns += sweep.column_entries() != entries_before;
    ASSERT_NO_FATAL_FAILURE(expect_brute_force_frame(sweep, boxes, ids, before, changes, frame));
    if (sides.empty() || sides.back() != sweep.column_side()) sides.push_back(sweep.column_side());
    most_outside = std::max(most_outside, sweep.boxes_outside_columns());
  }
  EXPECT_GE(sides.size(), 2u);       // the side was chosen again for the larger crowd
  EXPECT_GT(most_outside, 0u);       // the growing boxes left their columns
  EXPECT_GT(changed_columns, 30u);   // boxes crossed columns in most frames
  EXPECT_LT(sweep.swaps(), 60u * 450 * 4);  // coherence: a few swaps per box and frame
}

}  // namespace
}  // namespace cc::test
