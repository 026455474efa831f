#include "collide/sweep_and_prune.h"

#include <gtest/gtest.h>

#include <random>

#include "collide/broadphase_contract.h"

namespace cc::test {
namespace {

INSTANTIATE_TYPED_TEST_SUITE_P(SweepAndPrune, BroadphaseContract, ::testing::Types<SweepAndPrune>);

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
    ASSERT_NO_FATAL_FAILURE(expect_brute_force_frame(sap, boxes, ids, before, changes, frame));
  }
  EXPECT_LT(sap.swaps(), 60u * 200 * 20);  // coherence: a few swaps per box and frame
}

}  // namespace
}  // namespace cc::test
